// tests/rip/screen/screen_test.cpp: blue-noise ranks, tone reproduction, determinism by fabric
// coordinates and the error-diffusion reference screen.
#include "rip/screen/screen.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "rip/screen/blue_noise.h"

namespace tp::rip {
namespace {

std::vector<int> unpack(const std::vector<std::uint8_t>& packed, int width, int bits) {
  std::vector<int> codes(static_cast<size_t>(width));
  const int per = 8 / bits;
  for (int x = 0; x < width; ++x)
    codes[static_cast<size_t>(x)] = (packed[static_cast<size_t>(x / per)] >> (8 - bits - (x % per) * bits)) & ((1 << bits) - 1);
  return codes;
}

/// Mean code over an area screened at constant contone `v`.
double mean_code(Screen& s, const ScreenSetup& setup, std::uint8_t v, int rows) {
  std::vector<std::uint8_t> contone(static_cast<size_t>(padded_width(setup.width_px)), 0);
  std::fill(contone.begin(), contone.begin() + setup.width_px, v);
  std::vector<std::uint8_t> packed(static_cast<size_t>(packed_row_bytes(setup)));
  double sum = 0;
  for (int y = 0; y < rows; ++y) {
    s.screen_row(0, y, contone.data(), packed.data());
    for (int c : unpack(packed, setup.width_px, setup.bits_per_pixel)) sum += c;
  }
  return sum / (static_cast<double>(rows) * setup.width_px);
}

TEST(BlueNoise, RanksAreAPermutationWithoutLowFrequencyEnergy) {
  const auto& r = blue_noise_ranks();
  ASSERT_EQ(r.size(), static_cast<size_t>(kBlueNoiseSize * kBlueNoiseSize));
  std::vector<std::uint16_t> sorted = r;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  // The 10 % dot pattern: its power at the lowest frequencies must be far below white noise's
  // (expected power of white noise at any frequency: n * p * (1 - p)).
  const int n = kBlueNoiseSize;
  const double p = 0.1;
  double low = 0;
  int count = 0;
  for (int fy = 0; fy <= 3; ++fy)
    for (int fx = 0; fx <= 3; ++fx) {
      if (fx == 0 && fy == 0) continue;
      std::complex<double> acc = 0;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          if (r[static_cast<size_t>(y) * n + x] < p * n * n)
            acc += std::polar(1.0, -2 * std::numbers::pi * (fx * x + fy * y) / n);
      low += std::norm(acc);
      ++count;
    }
  const double white = n * n * p * (1 - p);
  EXPECT_LT(low / count, 0.05 * white);
}

TEST(ThresholdScreen, ReproducesToneAtEveryLevel) {
  ScreenSetup setup{ScreenKind::kBlueNoise, 1, 4, 2, 256};
  auto s = make_screen(setup);
  ASSERT_TRUE(s);
  for (int v : {0, 1, 40, 85, 128, 200, 254, 255}) {
    const double want = v * 3.0 / 255.0;
    EXPECT_NEAR(mean_code(**s, setup, static_cast<std::uint8_t>(v), 128), want, 0.01) << v;
  }
  // Solid ink is all large drops, no ink is nothing.
  EXPECT_DOUBLE_EQ(mean_code(**s, setup, 255, 16), 3.0);
  EXPECT_DOUBLE_EQ(mean_code(**s, setup, 0, 16), 0.0);
}

TEST(ThresholdScreen, BiLevelOnATwoBitHeadFiresLargeDrops) {
  ScreenSetup setup{ScreenKind::kBlueNoise, 1, 2, 2, 256};
  auto s = make_screen(setup);
  ASSERT_TRUE(s);
  EXPECT_NEAR(mean_code(**s, setup, 128, 128), 3.0 * 128 / 255, 0.02);
  ScreenSetup one_bit{ScreenKind::kBlueNoise, 1, 2, 1, 200};
  auto b = make_screen(one_bit);
  ASSERT_TRUE(b);
  EXPECT_NEAR(mean_code(**b, one_bit, 64, 128), 64 / 255.0, 0.01);
}

TEST(ThresholdScreen, DependsOnlyOnFabricCoordinatesAndInk) {
  ScreenSetup setup{ScreenKind::kBlueNoise, 2, 4, 2, 300};
  auto a = make_screen(setup);
  auto b = make_screen(setup);
  ASSERT_TRUE(a && b);
  std::vector<std::uint8_t> contone(static_cast<size_t>(padded_width(300)), 0);
  for (int x = 0; x < 300; ++x) contone[static_cast<size_t>(x)] = static_cast<std::uint8_t>(x * 255 / 299);
  std::vector<std::uint8_t> pa(75), pb(75), pc(75);
  // Same row in a different order and from a different screen object: same codes.
  for (int y : {5, 900, 131}) (*a)->screen_row(1, y, contone.data(), pa.data());
  (*b)->screen_row(1, 131, contone.data(), pb.data());
  EXPECT_EQ(pa, pb);
  // Another ink sees the tile elsewhere: different dots for the same tone.
  (*b)->screen_row(0, 131, contone.data(), pc.data());
  EXPECT_NE(pb, pc);
}

TEST(ErrorDiffusion, ReproducesToneAndAlternatesDirection) {
  ScreenSetup setup{ScreenKind::kErrorDiffusion, 1, 4, 2, 200};
  auto s = make_screen(setup);
  ASSERT_TRUE(s);
  for (int v : {10, 100, 170, 250}) EXPECT_NEAR(mean_code(**s, setup, static_cast<std::uint8_t>(v), 64), v * 3.0 / 255, 0.01) << v;
  // Bi-level error diffusion of a mid grey fires about half the pixels.
  ScreenSetup bi{ScreenKind::kErrorDiffusion, 1, 2, 1, 200};
  auto b = make_screen(bi);
  ASSERT_TRUE(b);
  EXPECT_NEAR(mean_code(**b, bi, 128, 64), 128 / 255.0, 0.01);
}

TEST(Screen, RejectsUnsupportedSetups) {
  EXPECT_FALSE(make_screen({ScreenKind::kBlueNoise, 4, 5, 2, 100}));
  EXPECT_FALSE(make_screen({ScreenKind::kBlueNoise, 4, 4, 3, 100}));
  EXPECT_FALSE(make_screen({ScreenKind::kBlueNoise, 0, 4, 2, 100}));
  auto e = make_screen({ScreenKind::kBlueNoise, 4, 4, 2, 0});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().code, ErrorCode::kScreen);
}

}  // namespace
}  // namespace tp::rip
