// tests/geometry/sewing/cloth_model_test.cpp: what the cloth model takes from a sewn garment's
// charts: plain seams' segments as rest-length edges (judged by the seam's run, not only the
// segment), eased seams' longer sides as gathered triangles.
#include <gtest/gtest.h>

#include "geometry/sewing/internal/cloth_model.h"
#include "geometry/sewing/internal/xpbd_solver.h"

namespace tp::geometry {
namespace {

// Two square-ish pieces sewn along one edge: piece A (100 x 100 mm) by its bottom edge to piece
// B's top edge, `b_width_mm` long in B's chart. 3D vertices 0 and 1 are the seam's ends.
Garment two_pieces_sewn(double b_width_mm) {
  Garment g;
  g.vertices_mm = {{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}, {0, -100, 0}, {100, -100, 0}};
  GarmentPiece a;
  a.mesh.vertices_mm = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  a.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  a.vertex_3d = {0, 1, 2, 3};
  GarmentPiece b;
  b.piece = 1;
  b.mesh.vertices_mm = {{0, 0}, {b_width_mm, 0}, {b_width_mm, 100}, {0, 100}};
  b.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  b.vertex_3d = {4, 5, 1, 0};
  g.pieces = {a, b};
  return g;
}

TEST(ClothModel, APlainSeamSegmentKeepsItsPatternLength) {
  const internal::ClothModel cm =
      internal::build_cloth_model(two_pieces_sewn(100), *cloth_material_preset("cotton-poplin"));
  ASSERT_EQ(cm.seam_edges.size(), 1u);
  EXPECT_EQ(cm.seam_edges[0].a, 0);
  EXPECT_EQ(cm.seam_edges[0].b, 1);
  EXPECT_DOUBLE_EQ(cm.seam_edges[0].rest_mm, 100);
  for (const auto& t : cm.triangles) EXPECT_EQ(t.min_stretch, 0);
}

TEST(ClothModel, ASegmentThatDiffersOnAPlainSeamKeepsItsLengthToo) {
  // A seam of two segments, 50 + 50 mm on A and 48.5 + 51.5 mm on B: each segment's sides differ
  // by 3 %, the seam's by none, so both are held (at their means), nothing is gathered.
  Garment g;
  g.vertices_mm = {{0, 0, 0}, {50, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}, {100, -100, 0}, {0, -100, 0}};
  GarmentPiece a;
  a.mesh.vertices_mm = {{0, 0}, {50, 0}, {100, 0}, {100, 100}, {0, 100}};
  a.mesh.triangles = {{0, 1, 4}, {1, 2, 3}, {1, 3, 4}};
  a.vertex_3d = {0, 1, 2, 3, 4};
  GarmentPiece b;
  b.piece = 1;
  b.mesh.vertices_mm = {{0, 0}, {48.5, 0}, {100, 0}, {100, -100}, {0, -100}};
  b.mesh.triangles = {{0, 4, 1}, {1, 3, 2}, {1, 4, 3}};
  b.vertex_3d = {0, 1, 2, 5, 6};
  g.pieces = {a, b};
  const internal::ClothModel cm = internal::build_cloth_model(g, *cloth_material_preset("cotton-poplin"));
  ASSERT_EQ(cm.seam_edges.size(), 2u);
  EXPECT_DOUBLE_EQ(cm.seam_edges[0].rest_mm, 49.25);
  EXPECT_DOUBLE_EQ(cm.seam_edges[1].rest_mm, 50.75);
  for (const auto& t : cm.triangles) EXPECT_EQ(t.min_stretch, 0);
  // B's side 30 mm longer in all: eased, the segments left to the membrane, B's side gathered.
  b.mesh.vertices_mm = {{0, 0}, {48.5, 0}, {130, 0}, {130, -100}, {0, -100}};
  g.pieces = {a, b};
  const internal::ClothModel eased = internal::build_cloth_model(g, *cloth_material_preset("cotton-poplin"));
  EXPECT_TRUE(eased.seam_edges.empty());
  EXPECT_GT(eased.triangles[4].min_stretch, 0);
}

TEST(ClothModel, AnEasedSeamGathersTheLongerSidesTrianglesAtIt) {
  // B's edge is 150 mm sewn to A's 100 mm: no single rest length, and B's two triangles (both
  // touch the seam) may compress to 100/150 (less a little slack).
  const internal::ClothModel cm =
      internal::build_cloth_model(two_pieces_sewn(150), *cloth_material_preset("cotton-poplin"));
  EXPECT_TRUE(cm.seam_edges.empty());
  ASSERT_EQ(cm.triangles.size(), 4u);
  EXPECT_EQ(cm.triangles[0].min_stretch, 0);
  EXPECT_EQ(cm.triangles[1].min_stretch, 0);
  EXPECT_NEAR(cm.triangles[2].min_stretch, 100.0 / 150 * internal::kGatherSlack, 1e-12);
  EXPECT_NEAR(cm.triangles[3].min_stretch, 100.0 / 150 * internal::kGatherSlack, 1e-12);
}

TEST(ClothModel, AGatheredTriangleKeepsItsCompressionButNotItsStretch) {
  // One triangle squeezed to 70 % along x: gathered down to 0.6 it stays as it is; plain, it is
  // pushed back towards its rest shape; stretched 130 % it is pulled back either way.
  internal::RestTriangle t;
  t.v = {0, 1, 2};
  t.rest_mm = {Vec2{-100.0 / 3, -100.0 / 3}, Vec2{200.0 / 3, -100.0 / 3}, Vec2{-100.0 / 3, 200.0 / 3}};
  t.dm_inv[0][0] = 0.01, t.dm_inv[1][1] = 0.01;
  const std::vector<double> w{1, 1, 1};
  auto width_after = [&](double min_stretch, double width_mm) {
    t.min_stretch = min_stretch;
    std::vector<Vec3> x{{0, 0, 0}, {width_mm, 0, 0}, {0, 100, 0}};
    internal::project_triangle(t, w, 0.03, 1.0, x);
    return x[1].x - x[0].x;
  };
  EXPECT_NEAR(width_after(0.6, 70), 70, 1e-9);
  EXPECT_GT(width_after(0, 70), 95);
  EXPECT_LT(width_after(0.6, 130), 105);
}

}  // namespace
}  // namespace tp::geometry
