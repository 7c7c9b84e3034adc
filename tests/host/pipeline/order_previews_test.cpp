// tests/host/pipeline/order_previews_test.cpp: one copy cut out of an order's merged garment
// (copies side by side) and moved back onto its body, for that size's print preview.
#include <gtest/gtest.h>

#include "host/pipeline/internal/order_run.h"

namespace tp::host::internal {
namespace {

// A piece of one triangle whose 3D corners start at vertex `first`.
geometry::GarmentPiece triangle_piece(int piece, int first) {
  geometry::GarmentPiece gp;
  gp.piece = piece;
  gp.mesh.vertices_mm = {{0, 0}, {10, 0}, {0, 10}};
  gp.mesh.triangles = {{0, 1, 2}};
  gp.vertex_3d = {first, first + 1, first + 2};
  return gp;
}

TEST(OrderPreviews, ACopyIsCutOutOfTheMergedGarmentAndMovedBackOntoItsBody) {
  // Two copies of two pieces each, the second 800 mm along x.
  geometry::Garment merged;
  for (int copy = 0; copy < 2; ++copy)
    for (int p = 0; p < 2; ++p) {
      const int first = static_cast<int>(merged.vertices_mm.size());
      for (int k = 0; k < 3; ++k) merged.vertices_mm.push_back({800.0 * copy + 10 * k, 1000.0 + p, 5});
      merged.pieces.push_back(triangle_piece(2 * copy + p, first));
    }
  OrderCopyRun second;
  second.first_piece = 2;
  second.piece_names = {"front.L.2", "back.L.2"};
  second.x_offset_mm = 800;
  const geometry::Garment g = order_copy_garment(merged, second);
  ASSERT_EQ(g.pieces.size(), 4u) << "pieces keep their place: the renderer is the order's";
  EXPECT_TRUE(g.pieces[0].vertex_3d.empty());
  EXPECT_TRUE(g.pieces[1].vertex_3d.empty());
  EXPECT_EQ(g.pieces[2].piece, 2);
  ASSERT_EQ(g.vertices_mm.size(), 6u) << "only the copy's vertices";
  for (const geometry::Vec3& v : g.vertices_mm) {
    EXPECT_GE(v.x, 0);
    EXPECT_LE(v.x, 20) << "moved back by its 800 mm";
  }
  EXPECT_EQ(g.vertices_mm[g.pieces[3].vertex_3d[0]].y, 1001);
}

}  // namespace
}  // namespace tp::host::internal
