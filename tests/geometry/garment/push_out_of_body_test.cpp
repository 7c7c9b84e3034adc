// tests/geometry/garment/push_out_of_body_test.cpp: pieces pushed out of the body as smooth sheets, clear ones kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/garment/initial_placement.h"
#include "geometry/garment/push_out_of_body.h"
#include "geometry/mesh/mesh_pattern.h"
#include "tests/geometry/garment/tube_fixture.h"

namespace tp::geometry {
namespace {

using namespace test_fixture;

// A flat panel at z = z0 (facing +z, x from -w/2), as its own placement would put it.
std::vector<Vec3> placed_flat(const PieceMesh& m, double w, double z0) {
  std::vector<Vec3> out;
  for (Vec2 v : m.vertices_mm) out.push_back({v.x - w / 2, 100 + v.y, z0});
  return out;
}

PatternMesh meshed(const Pattern& p) {
  TriangulateOptions to;
  to.target_edge_mm = 15;
  auto m = mesh_pattern(p, to);
  EXPECT_TRUE(m) << m.error().what();
  return std::move(*m);
}

TEST(PushOutOfBody, PanelThroughTheBodyEndsClearAndSmooth) {
  // A panel 300 mm wide cutting the cylinder (radius 100) 50 mm in front of its axis: its middle
  // 170 mm lie inside the body.
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p;
  p.pieces = {rectangle("front", 300, 300)};
  PatternMesh m = meshed(p);
  std::vector<std::vector<Vec3>> x{placed_flat(m.pieces[0], 300, 50)};
  const std::vector<Vec3> before = x[0];
  PushOutStats st;
  push_out_of_body(x, m, body, 10, kPushRadius_mm, &st);
  EXPECT_GT(st.inside_before, 100);
  EXPECT_EQ(st.inside_after, 0);
  EXPECT_EQ(st.close_after, 0);
  for (const Vec3& q : x[0]) EXPECT_GE(body.query(q).distance_mm, 9.9);
  // A sheet, not spikes: no triangle edge stretched or shrunk by more than a third.
  const PieceMesh& pm = m.pieces[0];
  double worst = 0;
  for (const auto& t : pm.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double rest = norm(before[a] - before[b]), now = norm(x[0][a] - x[0][b]);
      worst = std::max(worst, std::abs(now / rest - 1));
    }
  EXPECT_LT(worst, 0.34);
  EXPECT_GT(st.max_push_mm, 40);
}

TEST(PushOutOfBody, PiecesClearOfTheBodyAreNotMoved) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  PatternMesh m = meshed(p);
  std::vector<std::vector<Vec3>> x{placed_flat(m.pieces[0], p.pieces[0].edges[0].points_mm[1].x, 300)};
  const std::vector<Vec3> before = x[0];
  x.push_back(placed_flat(m.pieces[1], p.pieces[1].edges[0].points_mm[1].x, 400));
  PushOutStats st;
  push_out_of_body(x, m, body, 10, kPushRadius_mm, &st);
  EXPECT_EQ(st.inside_before, 0);
  EXPECT_EQ(st.passes, 0);
  for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(norm(x[0][i] - before[i]), 0);
}

TEST(PushOutOfBody, InitialPlacementStartsOutsideTheBody) {
  // The tube's panels placed 10 mm inside a thicker cylinder (radius 125): placement pushes them out.
  BodySdf body = cylinder_body(125, 0, 600);
  Pattern p = tube_pattern();
  PatternMesh m = meshed(p);
  PushOutStats st;
  auto x = initial_placement(p, m, body, kStartClearance_mm, &st);
  EXPECT_GT(st.inside_before, 0);
  EXPECT_EQ(st.inside_after, 0);
  for (const auto& piece : x)
    for (const Vec3& q : piece) EXPECT_GE(body.query(q).distance_mm, 0.95 * kStartClearance_mm);
}

}  // namespace
}  // namespace tp::geometry
