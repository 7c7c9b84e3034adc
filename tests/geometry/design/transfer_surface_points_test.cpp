// tests/geometry/design/transfer_surface_points_test.cpp: points moved between two meshings of one
// gore skirt (flat gores, so both meshes are the same surface) land where they were; a point off
// the surface lands on it and stays there; a garment of another pattern is refused.
#include "geometry/design/transfer_surface_points.h"

#include <gtest/gtest.h>

#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

TEST(TransferSurfacePoints, KeepsPointsOnTheSameSurfaceAcrossMeshings) {
  const auto coarse = test::gore_skirt(8, 120, 260, 600, 3, 8);
  const auto fine = test::gore_skirt(8, 120, 260, 600, 9, 40);
  // Points on the coarse mesh: its vertices' midpoints of a few triangles' edges, across gores.
  std::vector<Vec3> points;
  const auto& V = coarse.garment.vertices_mm;
  for (size_t i = 0; i + 7 < V.size(); i += 7) points.push_back((V[i] + V[i + 7]) * 0.5);
  ASSERT_GT(points.size(), 20u);
  // Project them on the coarse surface first (a midpoint of two vertices may cut a corner).
  auto on_coarse = transfer_surface_points(coarse.pattern, coarse.garment, coarse.garment, points);
  ASSERT_TRUE(on_coarse) << on_coarse.error().message;
  auto moved = transfer_surface_points(coarse.pattern, coarse.garment, fine.garment, *on_coarse);
  ASSERT_TRUE(moved) << moved.error().message;
  ASSERT_EQ(moved->size(), points.size());
  double worst = 0;
  for (size_t i = 0; i < points.size(); ++i) worst = std::max(worst, norm((*moved)[i] - (*on_coarse)[i]));
  EXPECT_LT(worst, 1e-6) << "flat gores meshed twice are one surface";
}

TEST(TransferSurfacePoints, PutsAPointOffTheSurfaceOnIt) {
  const auto skirt = test::gore_skirt();
  // 40 mm in front of the front gore's centre line, halfway down: lands on the front gore.
  const Vec3 p{0, -300, 190 + 40};
  auto moved = transfer_surface_points(skirt.pattern, skirt.garment, skirt.garment, {p});
  ASSERT_TRUE(moved) << moved.error().message;
  const Vec3 q = (*moved)[0];
  EXPECT_NEAR(q.x, 0, 1e-6) << "the front gore's centre line";
  EXPECT_LT(q.z, p.z - 30) << "the point moved onto the gore";
  // On the surface: moved again, it stays.
  auto again = transfer_surface_points(skirt.pattern, skirt.garment, skirt.garment, {q});
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_LT(norm((*again)[0] - q), 1e-6);
}

TEST(TransferSurfacePoints, RefusesAGarmentOfAnotherPattern) {
  const auto skirt = test::gore_skirt(8);
  const auto other = test::gore_skirt(6);
  auto moved = transfer_surface_points(skirt.pattern, skirt.garment, other.garment, {{0, -300, 200}});
  ASSERT_FALSE(moved);
  EXPECT_NE(moved.error().message.find("garment the points go to"), std::string::npos) << moved.error().message;
}

}  // namespace
}  // namespace tp::geometry
