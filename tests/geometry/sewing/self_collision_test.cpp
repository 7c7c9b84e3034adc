// tests/geometry/sewing/self_collision_test.cpp: the broad phase pairs cloth layers that lie close,
// of two pieces or of one piece folded over itself, and not a flat sheet's mesh neighbours.
#include "geometry/sewing/internal/self_collision.h"

#include <gtest/gtest.h>

#include "sheet_fixture.h"

namespace tp::geometry {
namespace {

constexpr double kStep_mm = 4;
constexpr double kMargin_mm = 7;  // the drape's: thickness 2 mm plus twice the 2.5 mm pad

internal::ClothModel model(const Garment& g) {
  return internal::build_cloth_model(g, *cloth_material_preset("cotton-poplin"));
}

// Every pair of primitives within one piece and within `cells` grid cells in the pattern.
int pairs_within(const internal::ClothModel& cloth, const internal::SelfCollisionPairs& pairs, double cells) {
  auto near = [&](int u, int v) {
    const Vec2 d = cloth.vertex_rest_mm[u] - cloth.vertex_rest_mm[v];
    return cloth.vertex_piece[u] == cloth.vertex_piece[v] && norm(d) <= cells * kStep_mm;
  };
  int n = 0;
  for (const auto& p : pairs.point_triangle)
    for (int v : cloth.triangles[p.triangle].v) n += near(p.vertex, v);
  for (const auto& p : pairs.edge_edge)
    for (int u : cloth.edges[p.edge_a])
      for (int v : cloth.edges[p.edge_b]) n += near(u, v);
  return n;
}

TEST(SelfCollision, FlatSheetHasNoPairsOfMeshNeighbours) {
  const internal::ClothModel cloth = model(test_fixture::flat_sheet(40 * kStep_mm, 40, 0));
  const auto pairs = internal::find_self_collision_pairs(cloth, cloth.x_mm, kMargin_mm);
  // Edges one triangle apart lie 2.8-4 mm apart, inside the margin: they are neighbours, not layers.
  EXPECT_EQ(pairs.point_triangle.size() + pairs.edge_edge.size(), 0u);
}

TEST(SelfCollision, TwoLayersThreeMillimetresApartArePaired) {
  Garment g;
  for (double y : {0.0, 3.0})
    test_fixture::add_grid_piece(g, 20, 20, kStep_mm, [&](int i, int j) {
      return Vec3{i * kStep_mm, y, j * kStep_mm};
    });
  const internal::ClothModel cloth = model(g);
  ThreadPool pool(2);
  const auto pairs = internal::find_self_collision_pairs(cloth, cloth.x_mm, kMargin_mm, &pool);
  ASSERT_GT(pairs.point_triangle.size(), 400u);  // about every vertex over the other layer's faces
  for (const auto& p : pairs.point_triangle)
    EXPECT_NE(cloth.vertex_piece[p.vertex], cloth.vertex_piece[cloth.triangles[p.triangle].v[0]]);
  EXPECT_EQ(pairs_within(cloth, pairs, 2), 0);
}

TEST(SelfCollision, OnePieceFoldedOverItselfIsPairedAcrossTheFold) {
  // A strip 60 cells long folded at cell 30: its far half lies 3 mm over its near half.
  Garment g;
  test_fixture::add_grid_piece(g, 60, 10, kStep_mm, [](int i, int j) {
    return i <= 30 ? Vec3{i * kStep_mm, 0, j * kStep_mm} : Vec3{(60 - i) * kStep_mm, 3, j * kStep_mm};
  });
  const internal::ClothModel cloth = model(g);
  const auto pairs = internal::find_self_collision_pairs(cloth, cloth.x_mm, kMargin_mm);
  int across = 0;
  for (const auto& p : pairs.point_triangle) {
    const double u = cloth.vertex_rest_mm[p.vertex].x / kStep_mm;
    const double t = cloth.vertex_rest_mm[cloth.triangles[p.triangle].v[0]].x / kStep_mm;
    across += (u < 25 && t > 35) || (u > 35 && t < 25);
  }
  EXPECT_GT(across, 200);
  EXPECT_EQ(pairs_within(cloth, pairs, 1), 0);
}

}  // namespace
}  // namespace tp::geometry
