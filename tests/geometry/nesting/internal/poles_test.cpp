// tests/geometry/nesting/internal/poles_test.cpp: poles stand inside the outline, apart from each
// other, largest first.
#include "geometry/nesting/internal/poles.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/nesting/internal/shape_prep.h"

namespace tp::geometry::nesting {
namespace {

TEST(ShapePrep, PolesAreInsideDisjointAndLargestFirst) {
  const Polygon base = *clean_polygon({{0, 0}, {100, 0}, {100, 20}, {20, 20}, {20, 80}, {0, 80}}, "ell");
  const auto poles = compute_poles(base);
  ASSERT_GE(poles.size(), 8u);
  for (size_t i = 0; i < poles.size(); ++i) {
    EXPECT_TRUE(point_in_polygon(base, poles[i].c));
    EXPECT_GE(distance_to_boundary(base, poles[i].c), poles[i].r * (1 - 1e-9));
    if (i > 0) {
      EXPECT_LE(poles[i].r, poles[i - 1].r * (1 + 1e-9));
    }
    for (size_t j = 0; j < i; ++j) EXPECT_GE(norm(poles[i].c - poles[j].c), (poles[i].r + poles[j].r) * (1 - 1e-9));
  }
  // The largest circle sits in the corner, touching both outer sides and the inner corner.
  EXPECT_NEAR(poles[0].r, 20 * std::sqrt(2.0) / (1 + std::sqrt(2.0)), 0.05);
}

}  // namespace
}  // namespace tp::geometry::nesting
