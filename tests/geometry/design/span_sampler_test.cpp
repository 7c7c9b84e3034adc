// tests/geometry/design/span_sampler_test.cpp: mip pyramid and span sampling: exact texels,
// wrapping, transparent borders, and no aliasing when a fine pattern is minified.
#include "geometry/design/internal/span_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/design/internal/mip_image.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry::internal {
namespace {

Rgba8 unpack(std::uint32_t t) { return unpremultiply(t); }

TEST(SpanSampler, BilinearHitsTexelCentresAndBlendsBetween) {
  auto img = test::make_image(2, 1, [](int x, int) { return x == 0 ? Rgba8{0, 0, 0, 255} : Rgba8{200, 100, 50, 255}; });
  const MipImage mip(*img, Wrap::kTransparent, Wrap::kTransparent);
  const SpanFilter f;
  EXPECT_EQ(unpack(sample_point(mip, f, 0.5, 0.5)), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(unpack(sample_point(mip, f, 1.5, 0.5)), (Rgba8{200, 100, 50, 255}));
  const Rgba8 mid = unpack(sample_point(mip, f, 1.0, 0.5));
  EXPECT_NEAR(mid.r, 100, 1);
  EXPECT_NEAR(mid.g, 50, 1);
}

TEST(SpanSampler, RepeatWrapsAcrossTheSeamOfTheTile) {
  auto img = test::make_image(4, 4, [](int x, int) { return Rgba8{static_cast<std::uint8_t>(x == 0 ? 200 : 0), 0, 0, 255}; });
  const MipImage mip(*img, Wrap::kRepeat, Wrap::kRepeat);
  const SpanFilter f;
  // Between the last column (0) and the first (200): half way.
  EXPECT_NEAR(unpack(sample_point(mip, f, 4.0, 1.5)).r, 100, 1);
  EXPECT_NEAR(unpack(sample_point(mip, f, 0.0, 1.5)).r, 100, 1);
  // Far tiles away and negative coordinates land on the same texels.
  EXPECT_EQ(unpack(sample_point(mip, f, 0.5 + 4 * 1000, 1.5 - 4 * 77)).r, 200);
  // A span walking across the wrap several times.
  std::uint32_t out[16];
  sample_span(mip, f, 0.5, 0.5, 1.0, 0.0, 16, out);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(unpack(out[k]).r, k % 4 == 0 ? 200 : 0) << k;
}

TEST(SpanSampler, TransparentOutsideTheImage) {
  auto img = test::make_image(8, 8, [](int, int) { return Rgba8{10, 20, 30, 255}; });
  const MipImage mip(*img, Wrap::kTransparent, Wrap::kTransparent);
  const SpanFilter f;
  EXPECT_EQ(sample_point(mip, f, -3, 4) >> 24, 0u);
  EXPECT_EQ(sample_point(mip, f, 4, 1e7) >> 24, 0u);
  EXPECT_EQ(sample_point(mip, f, 4, 4) >> 24, 255u);
  // Half a texel past the edge: half covered.
  EXPECT_NEAR(static_cast<double>(sample_point(mip, f, 8.0, 4) >> 24), 128, 1);
}

// Pixels sampling a 1-texel checkerboard 8 texels apart: a point sampler aliases (all black or
// all white); the mip pyramid gives the linear-light mean grey everywhere.
TEST(SpanSampler, MinifiedCheckerboardIsUniformGreyNotAliased) {
  auto img = test::make_image(256, 256, [](int x, int y) {
    const std::uint8_t v = ((x + y) & 1) ? 255 : 0;
    return Rgba8{v, v, v, 255};
  });
  const MipImage mip(*img, Wrap::kRepeat, Wrap::kRepeat);
  const SpanFilter f = choose_filter(mip, 8, 0, 0, 8);
  EXPECT_EQ(f.kind, SpanFilter::Kind::kTrilinear);
  EXPECT_EQ(f.level, 3);
  std::uint32_t out[64];
  sample_span(mip, f, 0.5, 0.5, 8, 0, 64, out);
  for (int k = 0; k < 64; ++k) EXPECT_NEAR(unpack(out[k]).r, 188, 2) << k;  // sRGB of 50 % linear
  const SpanFilter point;
  sample_span(mip, point, 0.5, 0.5, 8, 0, 64, out);
  EXPECT_EQ(unpack(out[0]).r, 0);  // the aliasing the pyramid removes
}

TEST(SpanSampler, AnisotropicFootprintsTakeTapsAlongTheMajorAxis) {
  auto img = test::make_image(256, 256, [](int x, int) {
    const std::uint8_t v = (x & 1) ? 255 : 0;
    return Rgba8{v, v, v, 255};
  });
  const MipImage mip(*img, Wrap::kRepeat, Wrap::kRepeat);
  // Eight texels per pixel across the stripes, one along them.
  const SpanFilter f = choose_filter(mip, 8, 0, 0, 1, 8);
  EXPECT_EQ(f.kind, SpanFilter::Kind::kAnisotropic);
  EXPECT_EQ(f.taps, 8);
  EXPECT_NEAR(std::abs(f.tap_du), 1.0, 1e-9);
  EXPECT_NEAR(f.tap_dv, 0.0, 1e-9);
  std::uint32_t out[32];
  sample_span(mip, f, 0.5, 0.5, 8, 0, 32, out);
  // Uniform (no aliasing). Taps blend in sRGB-encoded values, so the grey lies between the
  // encoded mean (128) and the linear-light mean (188) the pyramid levels give.
  for (int k = 0; k < 32; ++k) {
    EXPECT_NEAR(unpack(out[k]).r, unpack(out[0]).r, 2) << k;
    EXPECT_GE(unpack(out[k]).r, 126);
    EXPECT_LE(unpack(out[k]).r, 190);
  }
}

TEST(SpanSampler, MagnifiedFootprintsUseLevelZero) {
  auto img = test::make_image(16, 16, [](int, int) { return Rgba8{1, 2, 3, 255}; });
  const MipImage mip(*img, Wrap::kRepeat, Wrap::kRepeat);
  const SpanFilter f = choose_filter(mip, 0.1, 0.05, -0.05, 0.1);
  EXPECT_EQ(f.kind, SpanFilter::Kind::kBilinear);
  EXPECT_EQ(f.level, 0);
  EXPECT_EQ(mip.level_count(), 5);
}

TEST(MipImage, PremultipliedLevelsKeepTransparentFringesClean) {
  // A red opaque texel next to transparent black ones: filtering must not darken the red.
  auto img = test::make_image(2, 2, [](int x, int y) { return x == 0 && y == 0 ? Rgba8{255, 0, 0, 255} : Rgba8{0, 0, 0, 0}; });
  const MipImage mip(*img, Wrap::kRepeat, Wrap::kRepeat);
  const Rgba8 top = unpack(mip.level(1).origin()[0]);
  EXPECT_EQ(top.r, 255);
  EXPECT_NEAR(top.a, 64, 1);
}

}  // namespace
}  // namespace tp::geometry::internal
