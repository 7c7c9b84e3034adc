// tests/geometry/design/span_sampler_test.cpp: mip pyramid and span sampling: exact texels,
// wrapping, transparent borders, and no aliasing when a fine pattern is minified.
#include "geometry/design/raster/span_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/design/raster/mip_image.h"
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

// The span loop against the texel formula written out here (lerp_texel across, then down, on the
// level's padded texels), for random spans in both wrap modes and random premultiplied texels;
// and covered_range never leaves out a pixel that is not transparent.
TEST(SpanSampler, SpansMatchTheTexelFormulaAndCoveredRangeKeepsEveryVisiblePixel) {
  std::uint32_t seed = 12345;
  auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
  auto img = test::make_image(37, 23, [&](int, int) {
    const auto a = static_cast<std::uint8_t>(next() >> 24);
    return Rgba8{static_cast<std::uint8_t>(next() >> 24), static_cast<std::uint8_t>(next() >> 24),
                 static_cast<std::uint8_t>(next() >> 24), a};
  });
  for (Wrap wrap : {Wrap::kRepeat, Wrap::kTransparent}) {
    const MipImage mip(*img, wrap, wrap);
    const MipLevel& lv = mip.level(0);
    const SpanFilter f;
    for (int trial = 0; trial < 400; ++trial) {
      auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (next() >> 8) / double(1 << 24); };
      const double u0 = uniform(-60, 100), v0 = uniform(-40, 70), du = uniform(-0.9, 0.9), dv = uniform(-0.6, 0.6);
      constexpr int kN = 300;
      std::uint32_t out[kN];
      sample_span(mip, f, u0, v0, du, dv, kN, out);
      int k0 = 0, k1 = 0;
      covered_range(mip, f, u0, v0, du, dv, kN, k0, k1);
      ASSERT_LE(0, k0);
      ASSERT_LE(k0, k1);
      ASSERT_LE(k1, kN);
      // Reference: the same 32.32 fixed point walk, clamped or wrapped like the sampler.
      const auto one = std::int64_t{1} << 32;
      std::int64_t U = std::llround((u0 - 0.5) * 4294967296.0), V = std::llround((v0 - 0.5) * 4294967296.0);
      const std::int64_t sU = std::llround(du * 4294967296.0), sV = std::llround(dv * 4294967296.0);
      for (int k = 0; k < kN; ++k, U += sU, V += sV) {
        std::int64_t tu = U, tv = V;
        if (wrap == Wrap::kRepeat) {
          tu = ((tu % (lv.width * one)) + lv.width * one) % (lv.width * one);
          tv = ((tv % (lv.height * one)) + lv.height * one) % (lv.height * one);
        } else {
          tu = std::clamp<std::int64_t>(tu, -one, lv.width * one);
          tv = std::clamp<std::int64_t>(tv, -one, lv.height * one);
        }
        const std::uint32_t fx = static_cast<std::uint32_t>(tu >> 24) & 0xFF, fy = static_cast<std::uint32_t>(tv >> 24) & 0xFF;
        const std::uint32_t* p = lv.origin() + (tv >> 32) * lv.stride + (tu >> 32);
        const std::uint32_t want =
            lerp_texel(lerp_texel(p[0], p[1], fx), lerp_texel(p[lv.stride], p[lv.stride + 1], fx), fy);
        ASSERT_EQ(out[k], want) << "wrap " << int(wrap) << " trial " << trial << " pixel " << k;
        if (k < k0 || k >= k1) {
          ASSERT_EQ(out[k], 0u) << "outside covered_range " << k0 << ".." << k1 << ": pixel " << k;
        }
      }
      if (wrap == Wrap::kRepeat) {
        EXPECT_EQ(k1 - k0, kN);
      }
    }
  }
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
