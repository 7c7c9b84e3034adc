// tests/geometry/design/fit_cylinder_test.cpp: the cylinder fitted around a garment.
#include "geometry/design/fit_cylinder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tp::geometry {
namespace {

TEST(FitCylinder, RecoversACircleSeenAlongTheAxis) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 50; ++i) {
    const double a = 2 * std::numbers::pi * i / 50;
    pts.push_back({10 + 150 * std::cos(a), -200.0 + 8 * i, -20 + 150 * std::sin(a)});
  }
  // Points inside do not change the smallest enclosing circle.
  pts.push_back({10, 0, -20});
  const Cylinder c = fit_cylinder(pts, {0, 1, 0});
  EXPECT_NEAR(c.radius_mm, 150, 1e-6);
  EXPECT_NEAR(c.origin_mm.x, 10, 1e-6);
  EXPECT_NEAR(c.origin_mm.z, -20, 1e-6);
  EXPECT_NEAR(c.max_height_mm - c.min_height_mm, 8 * 49, 1e-9);
}

TEST(FitCylinder, AGivenOriginFixesTheAxis) {
  const std::vector<Vec3> pts{{100, 0, 0}, {-50, 10, 0}, {0, 20, 80}};
  const Cylinder c = fit_cylinder(pts, {0, 2, 0}, Vec3{0, 5, 0});
  EXPECT_NEAR(c.radius_mm, 100, 1e-9);
  EXPECT_NEAR(norm(c.direction - Vec3{0, 1, 0}), 0, 1e-12);
  EXPECT_NEAR(c.min_height_mm, -5, 1e-9);
  EXPECT_NEAR(c.max_height_mm, 15, 1e-9);
}

TEST(FitCylinder, EmptyAndDegenerateInput) {
  EXPECT_EQ(fit_cylinder({}, {0, 1, 0}).radius_mm, 0);
  const Cylinder c = fit_cylinder({{1, 2, 3}}, {0, 0, 0});
  EXPECT_EQ(c.radius_mm, 0);
  EXPECT_NEAR(c.direction.y, 1, 1e-12);
}

}  // namespace
}  // namespace tp::geometry
