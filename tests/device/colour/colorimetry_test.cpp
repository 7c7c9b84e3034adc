// tests/device/colour/colorimetry_test.cpp: CIEDE2000 against Sharma's published pairs, the
// D50 white, Lab round trips and sRGB white.
#include "device/colour/colorimetry.h"

#include <gtest/gtest.h>

namespace tp::device {
namespace {

TEST(Colorimetry, DeltaE2000MatchesSharmaWuDalalPairs) {
  // Pairs 1, 7, 17 and 19 of Sharma, Wu and Dalal (2005), Table 1, with their published dE00.
  struct Pair {
    Lab a, b;
    double de;
  };
  const Pair pairs[] = {{{50, 2.6772, -79.7751}, {50, 0, -82.7485}, 2.0425},
                        {{50, 0, 0}, {50, -1, 2}, 2.3669},
                        {{50, 2.5, 0}, {73, 25, -18}, 27.1492},
                        {{50, 2.5, 0}, {50, 0, -2.5}, 4.3065},
                        {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082}};
  for (const auto& p : pairs) {
    EXPECT_NEAR(delta_e_2000(p.a, p.b), p.de, 1e-4);
    EXPECT_NEAR(delta_e_2000(p.b, p.a), p.de, 1e-4) << "symmetric";
  }
}

TEST(Colorimetry, PerfectDiffuserIsD50WhiteAndSrgbWhite) {
  Spectrum ones;
  ones.fill(1.0);
  const Xyz w = spectrum_to_xyz(ones);
  EXPECT_NEAR(w.x, kD50White.x, 1e-9);
  EXPECT_NEAR(w.y, 1.0, 1e-9);
  EXPECT_NEAR(w.z, kD50White.z, 1e-9);
  const Lab l = xyz_to_lab(w);
  EXPECT_NEAR(l.l, 100, 1e-9);
  EXPECT_NEAR(l.a, 0, 1e-9);
  EXPECT_NEAR(l.b, 0, 1e-9);
  const auto rgb = xyz_to_srgb8(w);
  for (int k = 0; k < 3; ++k) EXPECT_GE(rgb[k], 254);
}

TEST(Colorimetry, SrgbDecodesToWhatItEncodes) {
  for (const auto& rgb : {std::array<std::uint8_t, 3>{255, 255, 255}, {200, 30, 90}, {12, 128, 250}}) {
    const auto back = xyz_to_srgb8(srgb8_to_xyz(rgb[0], rgb[1], rgb[2]));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], rgb[k], 1) << k;
  }
}

TEST(Colorimetry, BradfordTakesTheWhiteToTheWhite) {
  const Xyz paper{0.85, 0.88, 0.68};
  const Xyz w = adapt_bradford(paper, paper, kD50White);
  EXPECT_NEAR(w.x, kD50White.x, 1e-6);
  EXPECT_NEAR(w.y, kD50White.y, 1e-6);
  EXPECT_NEAR(w.z, kD50White.z, 1e-6);
}

TEST(Colorimetry, LabRoundTripsAndNeutralGreyStaysNeutral) {
  for (const Lab c : {Lab{50, 20, -30}, Lab{5, 0, 0}, Lab{90, -40, 60}}) {
    const Lab back = xyz_to_lab(lab_to_xyz(c));
    EXPECT_NEAR(back.l, c.l, 1e-9);
    EXPECT_NEAR(back.a, c.a, 1e-9);
    EXPECT_NEAR(back.b, c.b, 1e-9);
  }
  Spectrum grey;
  grey.fill(0.18);
  const Lab g = xyz_to_lab(spectrum_to_xyz(grey));
  EXPECT_NEAR(g.a, 0, 1e-9);
  EXPECT_NEAR(g.b, 0, 1e-9);
  EXPECT_NEAR(g.l, 49.5, 0.1);
}

}  // namespace
}  // namespace tp::device
