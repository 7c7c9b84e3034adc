// tests/simulator/fabric/fabric_preview_test.cpp: the preview's colour does not depend on its
// scale: a 3 x 3 preview pixel is the mean of the nine fabric pixels' colours.
#include "simulator/fabric/fabric_preview.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace tp::sim {
namespace {

std::vector<float> read_lab(const std::filesystem::path& path, int& width) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  return px;
}

TEST(FabricPreview, AnAreaIsTheMeanOfItsPixelsAtAnyScale) {
  FabricLook look;
  look.fabric = "cotton";
  look.inks = {"cyan", "magenta", "yellow", "black"};
  auto model = FabricColourModel::create(look, 2);
  ASSERT_TRUE(model) << model.error().message;
  constexpr int kSize = 24;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> level(0, 3);
  std::vector<std::uint8_t> fabric(kSize * kSize * 4);
  for (std::size_t i = 0; i < fabric.size(); ++i)
    fabric[i] = i % 4 == 3 ? 0 : static_cast<std::uint8_t>(level(rng) * (i % 4 != 1));
  const auto dir = std::filesystem::temp_directory_path() / ("tp-preview-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::vector<std::vector<float>> lab;
  for (int scale : {1, 3}) {
    PreviewSpec spec;
    spec.width_px = kSize;
    spec.height_px = kSize;
    spec.scale = scale;
    const auto png = dir / ("s" + std::to_string(scale) + ".png"), tif = dir / ("s" + std::to_string(scale) + ".tif");
    auto p = FabricPreview::open(*model, spec, png, tif);
    ASSERT_TRUE(p) << p.error().message;
    for (int y = 0; y < kSize; ++y)
      ASSERT_TRUE((*p)->add_row(
          std::span<const std::uint8_t>(fabric).subspan(static_cast<std::size_t>(y) * kSize * 4, kSize * 4)));
    ASSERT_TRUE((*p)->close());
    int w = 0;
    lab.push_back(read_lab(tif, w));
    EXPECT_EQ(w, kSize / scale);
  }
  std::filesystem::remove_all(dir);
  for (int by = 0; by < kSize / 3; ++by)
    for (int bx = 0; bx < kSize / 3; ++bx) {
      Xyz sum;
      for (int y = 3 * by; y < 3 * by + 3; ++y)
        for (int x = 3 * bx; x < 3 * bx + 3; ++x) {
          const float* l = &lab[0][(static_cast<std::size_t>(y) * kSize + x) * 3];
          const Xyz c = lab_to_xyz({l[0], l[1], l[2]});
          sum.x += c.x / 9;
          sum.y += c.y / 9;
          sum.z += c.z / 9;
        }
      const float* l = &lab[1][(static_cast<std::size_t>(by) * (kSize / 3) + bx) * 3];
      EXPECT_LT(delta_e_2000(xyz_to_lab(sum), {l[0], l[1], l[2]}), 0.01) << "block " << bx << "," << by;
    }
}

}  // namespace
}  // namespace tp::sim
