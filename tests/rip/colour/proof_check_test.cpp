// tests/rip/colour/proof_check_test.cpp: the proof check finds no difference where the fabric
// shows the design's colours on its own white, finds a shift, and leaves colour edges out.
#include "rip/colour/proof_check.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>

#include "device/colour/colorimetry.h"
#include "geometry/common/image.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

using device::Lab;
using device::Xyz;

constexpr int kW = 100, kH = 60;  // pixels at 25.4 dpi: 1 mm each
const geometry::Rgba8 kCream{240, 220, 180, 255};

// Design: white margin, a cream block in x 20..79, y 10..49.
bool in_block(int x, int y) { return x >= 20 && x < 80 && y >= 10 && y < 50; }

void write(const std::filesystem::path& p, OIIO::TypeDesc type, const void* px) {
  OIIO::ImageSpec s(kW, kH, 3, type);
  s.attribute("XResolution", 25.4f);
  s.attribute("YResolution", 25.4f);
  s.attribute("ResolutionUnit", "inch");
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out && out->open(p.string(), s));
  ASSERT_TRUE(out->write_image(type, px));
  ASSERT_TRUE(out->close());
}

// The fabric: a white of its own, the block as the design colour on that white (media-relative),
// shifted by `shift` in L*.
void write_pair(const std::filesystem::path& dir, double shift) {
  std::vector<std::uint8_t> rgb(kW * kH * 3, 255);
  std::vector<float> lab(kW * kH * 3);
  const Xyz white{0.86 * 0.9642, 0.88, 0.70 * 0.8249};
  const Xyz design = device::srgb8_to_xyz(kCream.r, kCream.g, kCream.b);
  const Xyz on_fabric = device::adapt_bradford(design, device::kD50White, {white.x / white.y, 1.0, white.z / white.y});
  Lab block = device::xyz_to_lab({on_fabric.x * white.y, on_fabric.y * white.y, on_fabric.z * white.y});
  block.l += shift;
  const Lab w = device::xyz_to_lab(white);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 3;
      const bool b = in_block(x, y);
      if (b) {
        rgb[i] = kCream.r;
        rgb[i + 1] = kCream.g;
        rgb[i + 2] = kCream.b;
      }
      const Lab& c = b ? block : w;
      lab[i] = static_cast<float>(c.l);
      lab[i + 1] = static_cast<float>(c.a);
      lab[i + 2] = static_cast<float>(c.b);
    }
  write(dir / "design.png", OIIO::TypeDesc::UINT8, rgb.data());
  write(dir / "fabric-lab.tif", OIIO::TypeDesc::FLOAT, lab.data());
}

TEST(ProofCheck, TheDesignOnItsOwnFabricWhiteMatches) {
  const auto dir = test::scratch_dir("proof-same");
  write_pair(dir, 0);
  auto r = check_proof(dir / "design.png", dir / "fabric-lab.tif", 1.0);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->cells, 58u * 38u) << "the block's interior, its edge cells out";
  EXPECT_GT(r->blank_cells, 0u);
  EXPECT_LT(r->mean_de00, 0.05);
  EXPECT_LT(r->max_de00, 0.05);
}

TEST(ProofCheck, AShiftedPrintShowsItsDifference) {
  const auto dir = test::scratch_dir("proof-shift");
  write_pair(dir, -3);
  auto r = check_proof(dir / "design.png", dir / "fabric-lab.tif", 1.0);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_NEAR(r->mean_de00, 3.0 / (1 + 0.015 * 2025 / std::sqrt(20 + 2025.0)) * 1.0, 0.6);
  EXPECT_GT(r->p95_de00, 2.0);
}

TEST(ProofCheck, RefusesUnreadableImages) {
  const auto dir = test::scratch_dir("proof-bad");
  auto r = check_proof(dir / "none.png", dir / "none.tif", 1.0);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("none.png"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::rip
