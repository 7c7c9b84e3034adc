// tests/simulator/fabric/fabric_canvas_test.cpp: drops land where swaths say, overlapping passes
// add up, long fabrics spill rows without losing any, and the TIFF and preview read back.
#include "simulator/fabric/fabric_canvas.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "tests/support/paths.h"

namespace tp::sim {
namespace {

FabricSpec spec() {
  FabricSpec s;
  s.width_px = 40;
  s.inks = {"cyan", "magenta", "yellow", "black"};
  s.reach_rows = 8;
  return s;
}

// A swath of `rows` rows whose every pixel of `channel` has drop level `level`.
device::SwathHeader header(std::uint32_t rows, std::int32_t x, std::uint32_t width) {
  device::SwathHeader h;
  h.rows = rows;
  h.x_start_px = x;
  h.width_px = width;
  h.channels = 4;
  h.bits_per_pixel = 2;
  h.raw_bytes = static_cast<std::uint32_t>(device::swath_raw_bytes(h));
  return h;
}

std::vector<std::uint8_t> fill(const device::SwathHeader& h, int channel, unsigned level) {
  std::vector<std::uint8_t> raw(h.raw_bytes, 0);
  const std::size_t rb = device::swath_row_bytes(h);
  for (std::uint32_t r = 0; r < h.rows; ++r)
    for (std::uint32_t x = 0; x < h.width_px; ++x) {
      const std::size_t bit = x * 2;
      raw[(channel * h.rows + r) * rb + bit / 8] |= static_cast<std::uint8_t>(level << (6 - bit % 8));
    }
  return raw;
}

std::vector<std::uint8_t> read_tiff(const std::filesystem::path& p, OIIO::ImageSpec& s) {
  OIIO::ImageSpec raw_config;
  raw_config.attribute("oiio:RawColor", 1);  // CMYK files: the ink samples, not RGB
  auto in = OIIO::ImageInput::open(p.string(), &raw_config);
  EXPECT_TRUE(in);
  if (!in) return {};
  s = in->spec();
  std::vector<std::uint8_t> px(static_cast<std::size_t>(s.width) * s.height * s.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, s.nchannels, OIIO::TypeDesc::UINT8, px.data()));
  return px;
}

TEST(FabricCanvas, LaysDropsWhereSwathsSayAndSumsOverlaps) {
  const auto dir = test::scratch_dir("canvas");
  auto c = FabricCanvas::create(spec(), dir / "scratch");
  ASSERT_TRUE(c);
  auto h = header(4, 10, 6);
  (*c)->lay(h, fill(h, 1, 2), 3);   // magenta level 2, rows 3..6, columns 10..15
  (*c)->lay(h, fill(h, 1, 1), 5);   // overlaps rows 5..6: level 3 there
  auto clipped = header(1, 38, 4);
  (*c)->lay(clipped, fill(clipped, 0, 3), 7);  // two of four pixels fall off the fabric
  auto sum = (*c)->finish(dir / "f.tif", dir / "f.png");
  ASSERT_TRUE(sum) << sum.error().message;
  EXPECT_EQ(sum->height_px, 9u);
  EXPECT_EQ(sum->clipped_pixels, 2u);
  OIIO::ImageSpec s;
  auto px = read_tiff(dir / "f.tif", s);
  ASSERT_EQ(s.nchannels, 4);
  ASSERT_EQ(s.width, 40);
  EXPECT_NE(s.get_string_attribute("ImageDescription").find("channels: cyan,magenta,yellow,black"), std::string::npos)
      << s.get_string_attribute("ImageDescription");
  auto at = [&](int x, int y, int ch) { return px[(static_cast<std::size_t>(y) * 40 + x) * 4 + ch]; };
  EXPECT_EQ(at(10, 3, 1), 2);
  EXPECT_EQ(at(15, 4, 1), 2);
  EXPECT_EQ(at(12, 5, 1), 3);
  EXPECT_EQ(at(12, 8, 1), 1);
  EXPECT_EQ(at(16, 4, 1), 0);
  EXPECT_EQ(at(9, 4, 1), 0);
  EXPECT_EQ(at(12, 2, 1), 0);
  EXPECT_EQ(at(12, 4, 0), 0);
  EXPECT_EQ(at(39, 7, 0), 3);
  OIIO::ImageSpec ps;
  auto prev = read_tiff(dir / "f.png", ps);
  ASSERT_EQ(ps.nchannels, 3);
  EXPECT_EQ(prev[(0 * 40 + 0) * 3 + 1], 255) << "blank fabric is white";
  EXPECT_LT(prev[(3 * 40 + 10) * 3 + 1], 128) << "magenta absorbs green";
}

TEST(FabricCanvas, SpillsLongFabricsWithinABoundedWindow) {
  const auto dir = test::scratch_dir("canvas-long");
  auto c = FabricCanvas::create(spec(), dir / "scratch");
  ASSERT_TRUE(c);
  auto h = header(8, 0, 40);
  for (int i = 0; i < 500; ++i) (*c)->lay(h, fill(h, i % 4, 1 + i % 3), i * 8);
  auto sum = (*c)->finish(dir / "f.tif", dir / "f.png", 16);
  ASSERT_TRUE(sum);
  EXPECT_EQ(sum->height_px, 4000u);
  EXPECT_LE(sum->peak_window_rows, 8u + 8u + 8u) << "memory holds a swath plus the head's reach";
  EXPECT_EQ(sum->preview_scale, 3);
  OIIO::ImageSpec s;
  auto px = read_tiff(dir / "f.tif", s);
  ASSERT_EQ(s.height, 4000);
  for (int i : {0, 1, 250, 499}) {
    const int y = i * 8 + 3;
    EXPECT_EQ(px[(static_cast<std::size_t>(y) * 40 + 20) * 4 + i % 4], 1 + i % 3) << "swath " << i;
  }
}

}  // namespace
}  // namespace tp::sim
