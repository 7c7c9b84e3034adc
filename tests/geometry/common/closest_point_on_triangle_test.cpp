// tests/geometry/common/closest_point_on_triangle_test.cpp: nearest point, weights and feature in every Voronoi region.
#include "geometry/common/closest_point_on_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tp::geometry {
namespace {

const Vec3 kA{0, 0, 0}, kB{4, 0, 0}, kC{0, 2, 0};

Vec3 from_weights(const TriangleClosestPoint& q, Vec3 a, Vec3 b, Vec3 c) {
  return a * q.bary[0] + b * q.bary[1] + c * q.bary[2];
}

TEST(ClosestPointOnTriangle, NamesTheFeatureOfEachRegion) {
  struct Case {
    Vec3 p, expect;
    int feature;
  };
  const Case cases[] = {
      {{1, 0.5, 3}, {1, 0.5, 0}, 0},  // above the face: straight down
      {{2, -1, 1}, {2, 0, 0}, 1},     // beyond edge ab
      {{3, 2, 0}, {2.4, 0.8, 0}, 2},  // beyond edge bc (x/4 + y/2 = 1)
      {{-1, 1, -2}, {0, 1, 0}, 3},    // beyond edge ca
      {{-1, -1, 0}, kA, 4},           // behind vertex a
      {{6, -1, 0}, kB, 5},            // beyond vertex b
      {{0, 5, 1}, kC, 6},             // beyond vertex c
  };
  for (const Case& k : cases) {
    const TriangleClosestPoint q = closest_point_on_triangle(k.p, kA, kB, kC);
    EXPECT_EQ(q.feature, k.feature) << k.p.x << "," << k.p.y << "," << k.p.z;
    EXPECT_NEAR(norm(q.point_mm - k.expect), 0, 1e-12) << k.feature;
    EXPECT_NEAR(norm(from_weights(q, kA, kB, kC) - q.point_mm), 0, 1e-12) << k.feature;
    EXPECT_NEAR(q.bary[0] + q.bary[1] + q.bary[2], 1, 1e-15);
  }
}

TEST(ClosestPointOnTriangle, IsNoFartherThanAnySampledPointOfTheTriangle) {
  // An independent check: dense barycentric samples of a skewed triangle are never nearer.
  const Vec3 a{1, 2, 3}, b{7, -1, 2}, c{2, 5, -4};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-10, 10);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    const TriangleClosestPoint q = closest_point_on_triangle(p, a, b, c);
    for (double w : q.bary) EXPECT_TRUE(w >= 0 && w <= 1);
    const double d = norm(p - q.point_mm);
    constexpr int kSteps = 40;
    for (int s = 0; s <= kSteps; ++s)
      for (int t = 0; s + t <= kSteps; ++t) {
        const double u = double(s) / kSteps, v = double(t) / kSteps;
        const Vec3 x = a * (1 - u - v) + b * u + c * v;
        ASSERT_LE(d, norm(p - x) + 1e-9) << "sample " << s << "," << t << " is nearer";
      }
  }
}

TEST(ClosestPointOnTriangle, ADegenerateTriangleGivesAFinitePoint) {
  const Vec3 a{0, 0, 0}, b{1, 1, 1}, c{2, 2, 2};
  const TriangleClosestPoint q = closest_point_on_triangle({1, 0, 1}, a, b, c);
  for (double w : q.bary) EXPECT_TRUE(std::isfinite(w));
  EXPECT_TRUE(std::isfinite(q.point_mm.x) && std::isfinite(q.point_mm.y) && std::isfinite(q.point_mm.z));
  const TriangleClosestPoint same = closest_point_on_triangle({1, 2, 3}, a, a, a);
  EXPECT_EQ(same.feature, 4);
}

}  // namespace
}  // namespace tp::geometry
