// tests/rip/image/image_io_test.cpp: reading images into sRGB (profiles, alpha, orientation, bit depths),
// writing PNG and multi-channel TIFF, and errors that name the file.
#include "rip/image/image_io.h"

#include <cmath>
#include <fstream>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <lcms2.h>

#include "tests/support/image_files.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

namespace OIIO = OIIO_NAMESPACE;
using geometry::ImageRgba8;
using geometry::Rgba8;

/// An Adobe-RGB-like wide-gamut profile built with lcms2 (no system profile files needed).
std::vector<std::uint8_t> wide_gamut_profile() {
  cmsCIExyY d65{0.3127, 0.3290, 1.0};
  cmsCIExyYTRIPLE primaries{{0.64, 0.33, 1.0}, {0.21, 0.71, 1.0}, {0.15, 0.06, 1.0}};
  cmsToneCurve* gamma = cmsBuildGamma(nullptr, 2.19921875);
  cmsToneCurve* curves[3] = {gamma, gamma, gamma};
  cmsHPROFILE p = cmsCreateRGBProfile(&d65, &primaries, curves);
  cmsUInt32Number n = 0;
  cmsSaveProfileToMem(p, nullptr, &n);
  std::vector<std::uint8_t> bytes(n);
  cmsSaveProfileToMem(p, bytes.data(), &n);
  cmsCloseProfile(p);
  cmsFreeToneCurve(gamma);
  return bytes;
}

/// What lcms2 itself makes of an RGB8 colour in `profile`, in sRGB 8-bit.
Rgba8 reference_to_srgb(const std::vector<std::uint8_t>& profile, Rgba8 in) {
  cmsHPROFILE src = cmsOpenProfileFromMem(profile.data(), static_cast<cmsUInt32Number>(profile.size()));
  cmsHPROFILE srgb = cmsCreate_sRGBProfile();
  cmsHTRANSFORM t = cmsCreateTransform(src, TYPE_RGB_16, srgb, TYPE_RGB_16, INTENT_RELATIVE_COLORIMETRIC,
                                       cmsFLAGS_BLACKPOINTCOMPENSATION);
  std::uint16_t i16[3] = {static_cast<std::uint16_t>(in.r * 257), static_cast<std::uint16_t>(in.g * 257),
                          static_cast<std::uint16_t>(in.b * 257)};
  std::uint16_t o16[3];
  cmsDoTransform(t, i16, o16, 1);
  cmsDeleteTransform(t);
  cmsCloseProfile(src);
  cmsCloseProfile(srgb);
  auto q = [](std::uint16_t v) { return static_cast<std::uint8_t>((v + 128) / 257); };
  return {q(o16[0]), q(o16[1]), q(o16[2]), 255};
}

ImageRgba8 gradient(int w, int h) {
  ImageRgba8 img;
  img.width_px = w;
  img.height_px = h;
  img.pixels.resize(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at(x, y) = {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 13),
                      static_cast<std::uint8_t>(x ^ y), static_cast<std::uint8_t>((x * 31 + y) & 255)};
  return img;
}

TEST(ImageIo, PngRoundTripKeepsStraightAlphaExactly) {
  auto dir = test::scratch_dir("image_io_png");
  ImageRgba8 img = gradient(37, 23);
  img.at(3, 4) = {200, 100, 50, 3};  // faint alpha: premultiplying would lose the colour
  ASSERT_TRUE(write_png(dir / "a.png", img));
  auto back = read_image(dir / "a.png");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->width_px, 37);
  EXPECT_EQ(back->height_px, 23);
  EXPECT_EQ(back->pixels, img.pixels);
  EXPECT_EQ(back->source, (dir / "a.png").string());
}

TEST(ImageIo, RgbPngIsCompositedOverWhiteFabric) {
  auto dir = test::scratch_dir("image_io_rgb");
  ImageRgba8 img = gradient(4, 1);
  img.pixels = {{0, 0, 0, 0}, {0, 0, 0, 255}, {100, 50, 0, 128}, {10, 20, 30, 255}};
  ASSERT_TRUE(write_png(dir / "rgb.png", img, PngChannels::kRgbOverWhite));
  auto back = read_image(dir / "rgb.png");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->at(0, 0), (Rgba8{255, 255, 255, 255}));
  EXPECT_EQ(back->at(1, 0), (Rgba8{0, 0, 0, 255}));
  // 100*128/255 + 255*127/255 = 177.2; 50 -> 152.1; 0 -> 127.0
  EXPECT_EQ(back->at(2, 0), (Rgba8{177, 152, 127, 255}));
  EXPECT_EQ(back->at(3, 0), (Rgba8{10, 20, 30, 255}));
}

TEST(ImageIo, GreyAndSixteenBitAreExpandedAndRounded) {
  auto dir = test::scratch_dir("image_io_grey16");
  std::uint16_t grey[4] = {0, 257 * 100, 257 * 100 + 128, 65535};  // 100.498 rounds to 100
  test::write_raw_image(dir / "g.png", OIIO::ImageSpec(4, 1, 1, OIIO::TypeDesc::UINT16), grey);
  auto back = read_image(dir / "g.png");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->at(0, 0), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(back->at(1, 0), (Rgba8{100, 100, 100, 255}));
  EXPECT_EQ(back->at(2, 0), (Rgba8{100, 100, 100, 255}));
  EXPECT_EQ(back->at(3, 0), (Rgba8{255, 255, 255, 255}));
}

TEST(ImageIo, EmbeddedProfileIsConvertedToSrgb) {
  auto dir = test::scratch_dir("image_io_icc");
  const auto profile = wide_gamut_profile();
  std::uint8_t px[3 * 3] = {40, 160, 90, 128, 128, 128, 200, 30, 30};
  OIIO::ImageSpec spec(3, 1, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, profile.size()), profile.data());
  test::write_raw_image(dir / "wide.tif", spec, px);
  auto back = read_image(dir / "wide.tif");
  ASSERT_TRUE(back) << back.error().what();
  for (int i = 0; i < 3; ++i) {
    Rgba8 in{px[3 * i], px[3 * i + 1], px[3 * i + 2], 255};
    Rgba8 want = reference_to_srgb(profile, in);
    Rgba8 got = back->at(i, 0);
    EXPECT_NEAR(got.r, want.r, 1) << i;
    EXPECT_NEAR(got.g, want.g, 1) << i;
    EXPECT_NEAR(got.b, want.b, 1) << i;
  }
  // A saturated wide-gamut green must come out visibly different from the raw numbers.
  EXPECT_GT(std::abs(back->at(0, 0).g - 160) + std::abs(back->at(0, 0).r - 40), 10);
}

TEST(ImageIo, UnreadableEmbeddedProfileIsRefusedNamingTheFile) {
  auto dir = test::scratch_dir("image_io_badicc");
  std::uint8_t px[3] = {1, 2, 3};
  std::vector<std::uint8_t> junk(200, 0x41);
  OIIO::ImageSpec spec(1, 1, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, junk.size()), junk.data());
  test::write_raw_image(dir / "junk.tif", spec, px);
  auto r = read_image(dir / "junk.tif");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kImage);
  EXPECT_NE(r.error().message.find("junk.tif"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("ICC"), std::string::npos) << r.error().message;
}

TEST(ImageIo, LinearPremultipliedFloatIsEncodedAndUnpremultiplied) {
  auto dir = test::scratch_dir("image_io_exr");
  // Premultiplied linear 0.1070 at alpha 0.5 is straight linear 0.2140 = sRGB 128.
  float px[2 * 4] = {0.1070f, 0.1070f, 0.1070f, 0.5f, 1.0f, 0.0f, 0.0f, 1.0f};
  OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::FLOAT);
  test::write_raw_image(dir / "lin.exr", spec, px);
  auto back = read_image(dir / "lin.exr");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_NEAR(back->at(0, 0).r, 128, 1);
  EXPECT_EQ(back->at(0, 0).a, 128);
  EXPECT_EQ(back->at(1, 0), (Rgba8{255, 0, 0, 255}));
}

TEST(ImageIo, ExifOrientationTurnsTheImageUpright) {
  auto dir = test::scratch_dir("image_io_orient");
  // Stored 3 wide, 2 high; orientation 6 means "rotate 90 degrees clockwise to display".
  test::write_oriented_tiff(dir / "o.tif");
  auto back = read_image(dir / "o.tif");
  ASSERT_TRUE(back);
  ASSERT_EQ(back->width_px, 2);
  ASSERT_EQ(back->height_px, 3);
  // Displayed top-left is the stored bottom-left (value 30), top-right the stored top-left (0).
  EXPECT_EQ(back->at(0, 0).r, 30);
  EXPECT_EQ(back->at(1, 0).r, 0);
  EXPECT_EQ(back->at(1, 2).r, 20);
}

TEST(ImageIo, MissingTruncatedAndGarbageFilesNameTheFile) {
  auto dir = test::scratch_dir("image_io_broken");
  auto missing = read_image(dir / "nope.png");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("nope.png"), std::string::npos);

  ASSERT_TRUE(write_png(dir / "full.png", gradient(64, 64)));
  std::ifstream f(dir / "full.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(f)), {});
  std::ofstream(dir / "cut.png", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  auto cut = read_image(dir / "cut.png");
  ASSERT_FALSE(cut);
  EXPECT_EQ(cut.error().code, ErrorCode::kImage);
  EXPECT_NE(cut.error().message.find("cut.png"), std::string::npos) << cut.error().message;

  std::ofstream(dir / "junk.png", std::ios::binary) << "this is not an image at all";
  auto junk = read_image(dir / "junk.png");
  ASSERT_FALSE(junk);
  EXPECT_NE(junk.error().message.find("junk.png"), std::string::npos) << junk.error().message;
}

TEST(ImageIo, ReadsFromMemory) {
  auto dir = test::scratch_dir("image_io_mem");
  ImageRgba8 img = gradient(9, 5);
  ASSERT_TRUE(write_png(dir / "m.png", img));
  std::ifstream f(dir / "m.png", std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)), {});
  auto back = read_image_from_memory(bytes, "m.png");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->pixels, img.pixels);
}

// In memory at any zlib level: the pixels write_png stores (RGBA exactly; RGB over white), and
// level 1 packs a smooth image less tightly than 9, so the level reaches the encoder.
TEST(ImageIo, EncodePngInMemoryKeepsThePixelsAtEveryLevel) {
  auto dir = test::scratch_dir("image_io_encode");
  const ImageRgba8 img = gradient(120, 80);
  ASSERT_TRUE(write_png(dir / "rgb.png", img, PngChannels::kRgbOverWhite, 16));
  auto file = read_image(dir / "rgb.png");
  ASSERT_TRUE(file);
  std::size_t fast_bytes = 0, small_bytes = 0;
  for (int level : {1, 9}) {
    auto rgba = encode_png(img, PngChannels::kRgba, 0, level);
    auto rgb = encode_png(img, PngChannels::kRgbOverWhite, 16, level);
    ASSERT_TRUE(rgba && rgb) << (rgba ? rgb.error().what() : rgba.error().what());
    auto a =
        read_image_from_memory(std::span(reinterpret_cast<const std::uint8_t*>(rgba->data()), rgba->size()), "a.png");
    auto b =
        read_image_from_memory(std::span(reinterpret_cast<const std::uint8_t*>(rgb->data()), rgb->size()), "b.png");
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->pixels, img.pixels) << "level " << level;
    EXPECT_EQ(b->pixels, file->pixels) << "level " << level;
    (level == 1 ? fast_bytes : small_bytes) = rgb->size();
  }
  EXPECT_GT(fast_bytes, small_bytes);
  ImageRgba8 bad = img;
  bad.pixels.resize(3);
  auto refused = encode_png(bad, PngChannels::kRgba, 0, 1, "preview of x");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("preview of x"), std::string::npos);
}

TEST(ImageIo, WritePngRejectsInconsistentImages) {
  auto dir = test::scratch_dir("image_io_badpng");
  ImageRgba8 img;
  img.width_px = 3;
  img.height_px = 3;
  img.pixels.resize(4);
  auto s = write_png(dir / "x.png", img);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("x.png"), std::string::npos);
  auto unwritable = write_png(dir / "no_such_dir" / "y.png", gradient(2, 2));
  ASSERT_FALSE(unwritable);
  EXPECT_EQ(unwritable.error().code, ErrorCode::kIo);
  EXPECT_NE(unwritable.error().message.find("y.png"), std::string::npos);
}

TEST(ImageIo, MultiChannelTiffKeepsChannelsAndLevels) {
  auto dir = test::scratch_dir("image_io_tiff");
  for (int bits : {8, 2, 1}) {
    ChannelImage8 img;
    img.width_px = 13;
    img.height_px = 4;
    img.channel_names = {"cyan", "magenta", "yellow", "black", "red"};
    const unsigned maxv = (1u << bits) - 1;
    for (int i = 0; i < 13 * 4 * 5; ++i) img.samples.push_back(static_cast<std::uint8_t>((i * 7) % (maxv + 1)));
    auto path = dir / ("sep" + std::to_string(bits) + ".tif");
    ASSERT_TRUE(write_tiff(path, img, bits)) << bits;
    auto back = read_channels8(path);
    ASSERT_TRUE(back) << back.error().what();
    EXPECT_EQ(back->channel_names, img.channel_names) << bits;
    EXPECT_EQ(back->samples, img.samples) << bits;
  }
  ChannelImage8 bad;
  bad.width_px = 2;
  bad.height_px = 2;
  bad.channel_names = {"k"};
  bad.samples.resize(3);
  auto s = write_tiff(dir / "bad.tif", bad);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("bad.tif"), std::string::npos);
  EXPECT_FALSE(write_tiff(dir / "bad3.tif", bad, 3));
}

}  // namespace
}  // namespace tp::rip
