// tests/geometry/continuity/ciede2000_agreement_test.cpp: the two CIEDE2000 implementations (the
// geometry layer's, for contone continuity, and device/colour's, for the colour code) give the
// same difference on the same pairs. They stay two because geometry may not depend on device and
// device is standard-library only (scripts/check-layers, docs/colour.md).
#include <gtest/gtest.h>

#include <random>

#include "device/colour/colorimetry.h"
#include "geometry/continuity/ciede2000.h"

namespace tp::geometry {
namespace {

TEST(Ciede2000Agreement, BothLayersGiveTheSameDifference) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> L(0, 100), ab(-120, 120), small(-3, 3);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const Lab a{L(rng), ab(rng), ab(rng)};
    // Half the pairs near each other (the seam differences), half anywhere; a few achromatic.
    Lab b = i % 2 ? Lab{L(rng), ab(rng), ab(rng)} : Lab{a.L + small(rng), a.a + small(rng), a.b + small(rng)};
    if (i % 97 == 0) b.a = b.b = 0;
    const double g = ciede2000(a, b);
    const double d = device::delta_e_2000({a.L, a.a, a.b}, {b.L, b.a, b.b});
    worst = std::max(worst, std::abs(g - d));
  }
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace tp::geometry
