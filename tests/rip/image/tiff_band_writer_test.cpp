// tests/rip/image/tiff_band_writer_test.cpp: the streaming separation TIFF writer read back through
// OpenImageIO and libtiff: bit depths, packed rows, strips, compressions, BigTIFF, resolution, the
// separated tags (Photometric, InkSet, InkNames, no ExtraSamples), errors.
#include "rip/image/tiff_band_writer.h"

#include <fstream>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <tiffio.h>

#include "tests/support/paths.h"

namespace tp::rip {
namespace {

TEST(TiffBandWriter, PackedRowsInStripsRoundTripForEveryCompression) {
  auto dir = test::scratch_dir("tiff_band_writer");
  const int w = 37, h = 600;  // 10 bytes a row: 256 rows a strip, so three strips
  for (auto comp : {TiffCompression::kNone, TiffCompression::kPackBits, TiffCompression::kDeflate}) {
    for (bool big : {false, true}) {
      const auto path = dir / ("p" + std::to_string(static_cast<int>(comp)) + (big ? "b" : "c") + ".tif");
      auto wr = TiffBandWriter::open(path, w, h, {"magenta"}, 2, comp, 600, 600, big);
      ASSERT_TRUE(wr) << wr.error().what();
      std::vector<std::uint8_t> packed(10);
      for (int y = 0; y < h; y += 3) {
        // Three rows at a time from a buffer 16 bytes a row (the stride is not the row size).
        std::vector<std::uint8_t> rows(48, 0);
        for (int r = 0; r < 3; ++r)
          for (int b = 0; b < 10; ++b) rows[static_cast<size_t>(r) * 16 + b] = static_cast<std::uint8_t>((y + r) * 7 + b * 13);
        for (int r = 0; r < 3; ++r) rows[static_cast<size_t>(r) * 16 + 9] &= 0xC0;  // pad bits of the last byte stay 0
        ASSERT_TRUE((*wr)->write_packed_rows(3, rows.data(), 16));
      }
      ASSERT_TRUE((*wr)->close());
      auto back = read_channels8(path);
      ASSERT_TRUE(back) << back.error().what();
      EXPECT_EQ(back->channel_names, std::vector<std::string>{"magenta"});
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int byte = ((y * 7 + (x / 4) * 13) & 0xff) & (x / 4 == 9 ? 0xC0 : 0xff);
          ASSERT_EQ(back->samples[static_cast<size_t>(y) * w + x], (byte >> (6 - 2 * (x % 4))) & 3)
              << path << " " << x << "," << y;
        }
      auto in = OIIO_NAMESPACE::ImageInput::open(path.string());
      ASSERT_TRUE(in);
      EXPECT_FLOAT_EQ(in->spec().get_float_attribute("XResolution"), 600.0f);
      std::ifstream f(path, std::ios::binary);
      char head[4] = {};
      f.read(head, 4);
      EXPECT_EQ(head[2], big ? 43 : 42) << "TIFF version of " << path;
    }
  }
}

TEST(TiffBandWriter, InterleavedSamplesPackPerPixel) {
  auto dir = test::scratch_dir("tiff_band_writer_il");
  auto wr = TiffBandWriter::open(dir / "i.tif", 5, 2, {"c", "m", "y"}, 1, TiffCompression::kPackBits);
  ASSERT_TRUE(wr);
  const std::vector<std::uint8_t> s = {1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0, 1,
                                       0, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0};
  ASSERT_TRUE((*wr)->write_rows(2, s.data(), 15));
  ASSERT_TRUE((*wr)->close());
  auto back = read_channels8(dir / "i.tif");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->samples, s);
  EXPECT_EQ(back->channel_names, (std::vector<std::string>{"c", "m", "y"}));
}

TEST(TiffBandWriter, RowCountIsEnforced) {
  auto dir = test::scratch_dir("tiff_band_writer_err");
  auto wr = TiffBandWriter::open(dir / "e.tif", 4, 2, {"k"}, 8, TiffCompression::kNone);
  ASSERT_TRUE(wr);
  std::vector<std::uint8_t> row(4, 9);
  ASSERT_TRUE((*wr)->write_rows(1, row.data(), 4));
  auto early = (*wr)->close();
  ASSERT_FALSE(early);
  EXPECT_NE(early.error().message.find("e.tif"), std::string::npos);
  auto wr2 = TiffBandWriter::open(dir / "f.tif", 4, 1, {"k"}, 8, TiffCompression::kNone);
  ASSERT_TRUE(wr2);
  auto over = (*wr2)->write_rows(2, row.data(), 0);
  ASSERT_FALSE(over);
  EXPECT_NE(over.error().message.find("f.tif"), std::string::npos);
  EXPECT_FALSE(TiffBandWriter::open(dir / "no_dir" / "g.tif", 4, 1, {"k"}, 8, TiffCompression::kNone));
  EXPECT_FALSE(TiffBandWriter::open(dir / "h.tif", 4, 1, {"k"}, 3, TiffCompression::kNone));
}

/// The separated tags of a TIFF as libtiff reads them.
struct SeparatedTags {
  bool opened = false;
  std::uint16_t photometric = 0, inkset = 0, samples = 0, bits = 0, extra = 0, compression = 0;
  std::vector<std::string> inks;
  float x_dpi = 0, y_dpi = 0;
};

SeparatedTags read_tags(const std::filesystem::path& p) {
  SeparatedTags t;
  TIFF* tif = TIFFOpen(p.c_str(), "r");
  if (!tif) return t;
  t.opened = true;
  TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &t.photometric);
  TIFFGetFieldDefaulted(tif, TIFFTAG_INKSET, &t.inkset);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &t.samples);
  TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &t.bits);
  TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &t.compression);
  std::uint16_t* types = nullptr;
  if (TIFFGetField(tif, TIFFTAG_EXTRASAMPLES, &t.extra, &types) != 1) t.extra = 0;
  char* names = nullptr;
  if (TIFFGetField(tif, TIFFTAG_INKNAMES, &names) == 1 && names) {
    // NUL-separated; libtiff keeps the whole value, its length from the samples' count.
    const char* at = names;
    for (int i = 0; i < t.samples && *at; ++i) {
      t.inks.emplace_back(at);
      at += t.inks.back().size() + 1;
    }
  }
  TIFFGetField(tif, TIFFTAG_XRESOLUTION, &t.x_dpi);
  TIFFGetField(tif, TIFFTAG_YRESOLUTION, &t.y_dpi);
  TIFFClose(tif);
  return t;
}

TEST(TiffBandWriter, CmykIsSeparatedWithInkSetCmykAndNoAlpha) {
  auto dir = test::scratch_dir("tiff_band_writer_cmyk");
  const std::vector<std::string> cmyk = {"cyan", "magenta", "yellow", "black"};
  auto wr = TiffBandWriter::open(dir / "s.tif", 8, 3, cmyk, 2, TiffCompression::kDeflate, 720, 360);
  ASSERT_TRUE(wr) << wr.error().what();
  std::vector<std::uint8_t> s(8 * 3 * 4);
  for (size_t i = 0; i < s.size(); ++i) s[i] = static_cast<std::uint8_t>(i % 4);
  ASSERT_TRUE((*wr)->write_rows(3, s.data(), 32));
  ASSERT_TRUE((*wr)->close());
  const SeparatedTags t = read_tags(dir / "s.tif");
  ASSERT_TRUE(t.opened);
  EXPECT_EQ(t.photometric, PHOTOMETRIC_SEPARATED);
  EXPECT_EQ(t.inkset, INKSET_CMYK);
  EXPECT_EQ(t.samples, 4);
  EXPECT_EQ(t.bits, 2);
  EXPECT_EQ(t.extra, 0) << "no channel may read as alpha";
  EXPECT_EQ(t.compression, COMPRESSION_ADOBE_DEFLATE);
  EXPECT_EQ(t.inks, cmyk);
  EXPECT_FLOAT_EQ(t.x_dpi, 720);
  EXPECT_FLOAT_EQ(t.y_dpi, 360);
  auto back = read_channels8(dir / "s.tif");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->samples, s) << "the ink samples, not RGB";
}

TEST(TiffBandWriter, OtherInkSetsAreMultiInkWithOneNamePerChannel) {
  auto dir = test::scratch_dir("tiff_band_writer_multi");
  const std::vector<std::string> inks = {"cyan", "magenta", "yellow", "black", "orange", "green"};
  for (const auto& set : {inks, std::vector<std::string>{"black"}, std::vector<std::string>{"black", "cyan", "magenta", "yellow"}}) {
    const auto path = dir / (std::to_string(set.size()) + set.front() + ".tif");
    auto wr = TiffBandWriter::open(path, 5, 2, set, 8, TiffCompression::kPackBits, 600, 600);
    ASSERT_TRUE(wr) << wr.error().what();
    std::vector<std::uint8_t> s(5 * 2 * set.size(), 7);
    ASSERT_TRUE((*wr)->write_rows(2, s.data(), static_cast<std::ptrdiff_t>(5 * set.size())));
    ASSERT_TRUE((*wr)->close());
    const SeparatedTags t = read_tags(path);
    ASSERT_TRUE(t.opened) << path;
    EXPECT_EQ(t.photometric, PHOTOMETRIC_SEPARATED) << path;
    EXPECT_EQ(t.inkset, INKSET_MULTIINK) << path << ": only cyan, magenta, yellow, black in that order is CMYK";
    EXPECT_EQ(t.extra, 0) << path;
    EXPECT_EQ(t.compression, COMPRESSION_PACKBITS) << path;
    EXPECT_EQ(t.inks, set) << path;
    auto back = read_channels8(path);
    ASSERT_TRUE(back) << back.error().what();
    EXPECT_EQ(back->channel_names, set);
    EXPECT_EQ(back->samples, s);
  }
  EXPECT_FALSE(TiffBandWriter::open(dir / "bad.tif", 4, 1, {"cyan", "ma,genta"}, 8, TiffCompression::kNone));
}

}  // namespace
}  // namespace tp::rip
