// tests/simulator/fabric/fabric_tiff_test.cpp: the fabric TIFF read back with libtiff: separated
// CMYK or named multi-ink channels, no alpha, the print resolution, every sample; errors name the file.
#include "simulator/fabric/fabric_tiff.h"

#include <gtest/gtest.h>
#include <tiffio.h>

#include "tests/support/paths.h"

namespace tp::sim {
namespace {

struct Read {
  std::uint16_t photometric = 0, inkset = 0, samples = 0, extra = 0;
  std::vector<std::string> inks;
  float x_dpi = 0, y_dpi = 0;
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

Read read_back(const std::filesystem::path& p) {
  Read r;
  TIFF* tif = TIFFOpen(p.c_str(), "r");
  EXPECT_TRUE(tif) << p;
  if (!tif) return r;
  TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &r.photometric);
  TIFFGetFieldDefaulted(tif, TIFFTAG_INKSET, &r.inkset);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &r.samples);
  std::uint16_t* types = nullptr;
  if (TIFFGetField(tif, TIFFTAG_EXTRASAMPLES, &r.extra, &types) != 1) r.extra = 0;
  char* names = nullptr;
  if (TIFFGetField(tif, TIFFTAG_INKNAMES, &names) == 1 && names)
    for (const char* at = names; r.inks.size() < r.samples && *at; at += r.inks.back().size() + 1) r.inks.emplace_back(at);
  TIFFGetField(tif, TIFFTAG_XRESOLUTION, &r.x_dpi);
  TIFFGetField(tif, TIFFTAG_YRESOLUTION, &r.y_dpi);
  TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &r.width);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &r.height);
  const tmsize_t line = TIFFScanlineSize(tif);
  r.pixels.resize(static_cast<size_t>(line) * r.height);
  for (std::uint32_t y = 0; y < r.height; ++y)
    EXPECT_EQ(TIFFReadScanline(tif, r.pixels.data() + static_cast<size_t>(line) * y, y, 0), 1) << p << " row " << y;
  TIFFClose(tif);
  return r;
}

std::vector<std::uint8_t> write(const std::filesystem::path& p, const std::vector<std::string>& inks, int w, int h) {
  auto t = FabricTiff::open(p, static_cast<std::uint32_t>(w), static_cast<std::uint64_t>(h), inks, 600, 300);
  EXPECT_TRUE(t) << (t ? "" : t.error().message);
  std::vector<std::uint8_t> all;
  if (!t) return all;
  for (int y = 0; y < h; ++y) {
    std::vector<std::uint8_t> row(static_cast<size_t>(w) * inks.size());
    for (size_t i = 0; i < row.size(); ++i) row[i] = static_cast<std::uint8_t>((y * 31 + i * 7) % 256);
    EXPECT_TRUE((*t)->write_row(row.data()));
    all.insert(all.end(), row.begin(), row.end());
  }
  EXPECT_TRUE((*t)->close());
  return all;
}

TEST(FabricTiff, CmykInksAreSeparatedCmykWithoutAlphaAtThePrintResolution) {
  const auto dir = test::scratch_dir("fabric_tiff_cmyk");
  const std::vector<std::string> inks = {"cyan", "magenta", "yellow", "black"};
  const auto written = write(dir / "f.tif", inks, 33, 70);
  const Read r = read_back(dir / "f.tif");
  EXPECT_EQ(r.photometric, PHOTOMETRIC_SEPARATED);
  EXPECT_EQ(r.inkset, INKSET_CMYK);
  EXPECT_EQ(r.samples, 4);
  EXPECT_EQ(r.extra, 0) << "no channel may read as alpha";
  EXPECT_EQ(r.inks, inks);
  EXPECT_FLOAT_EQ(r.x_dpi, 600);
  EXPECT_FLOAT_EQ(r.y_dpi, 300);
  EXPECT_EQ(r.width, 33u);
  EXPECT_EQ(r.height, 70u);
  EXPECT_EQ(r.pixels, written);
}

TEST(FabricTiff, OtherInkSetsGetOneNamedChannelPerInk) {
  const auto dir = test::scratch_dir("fabric_tiff_multi");
  const std::vector<std::string> inks = {"cyan", "magenta", "yellow", "black", "light_cyan", "light_magenta"};
  const auto written = write(dir / "f.tif", inks, 9, 4);
  const Read r = read_back(dir / "f.tif");
  EXPECT_EQ(r.photometric, PHOTOMETRIC_SEPARATED);
  EXPECT_EQ(r.inkset, INKSET_MULTIINK);
  EXPECT_EQ(r.samples, 6);
  EXPECT_EQ(r.extra, 0);
  EXPECT_EQ(r.inks, inks);
  EXPECT_EQ(r.pixels, written);
}

TEST(FabricTiff, MissingRowsAndBadSizesFailNamingTheFile) {
  const auto dir = test::scratch_dir("fabric_tiff_err");
  auto t = FabricTiff::open(dir / "short.tif", 4, 3, {"black"}, 600, 600);
  ASSERT_TRUE(t);
  std::vector<std::uint8_t> row(4, 1);
  ASSERT_TRUE((*t)->write_row(row.data()));
  auto closed = (*t)->close();
  ASSERT_FALSE(closed);
  EXPECT_NE(closed.error().message.find("short.tif"), std::string::npos) << closed.error().message;
  EXPECT_FALSE(FabricTiff::open(dir / "zero.tif", 0, 3, {"black"}, 600, 600));
  EXPECT_FALSE(FabricTiff::open(dir / "noinks.tif", 4, 3, {}, 600, 600));
  auto nodir = FabricTiff::open(dir / "no_dir" / "f.tif", 4, 3, {"black"}, 600, 600);
  ASSERT_FALSE(nodir);
  EXPECT_NE(nodir.error().message.find("no_dir"), std::string::npos) << nodir.error().message;
}

}  // namespace
}  // namespace tp::sim
