// tests/geometry/garment/initial_placement_test.cpp: panels rolled round the body fit side by side.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/garment/initial_placement.h"
#include "geometry/mesh/mesh_pattern.h"
#include "tests/geometry/garment/tube_fixture.h"

namespace tp::geometry {
namespace {

using namespace test_fixture;

TEST(InitialPlacement, FrontAndBackTooWideForTheirDistanceDoNotWrapIntoEachOther) {
  // GarmentCode 2021's skirt_2_panels in small: two flat panels 600 mm wide, the front 150 mm in
  // front of the body's axis and the back 120 mm behind it. Rolled each at its own distance they
  // would reach 2.0 and 2.5 rad round from their middles, past the sides into each other (the
  // side seams start crossed); together they fit round a circle of 600 / pi = 191 mm.
  const double w = 600, h = 300;
  BodySdf body = cylinder_body(100, 0, 600);
  const Pattern p = two_panels("two_panels", w, h, 150, 150, -120);
  TriangulateOptions to;
  to.target_edge_mm = 20;
  auto m = mesh_pattern(p, to);
  ASSERT_TRUE(m) << m.error().what();
  PushOutStats st;
  const auto x = initial_placement(p, *m, body, kStartClearance_mm, &st);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(st.inside_after, 0);
  // Azimuth from the front (+z): the front covers [-pi/2, pi/2], the back the rest.
  const double slack = 0.02;
  for (const Vec3& q : x[0]) {
    EXPECT_LE(std::abs(std::atan2(q.x, q.z)), kPi / 2 + slack);
    EXPECT_NEAR(std::hypot(q.x, q.z), w / kPi, 0.5);
  }
  for (const Vec3& q : x[1]) {
    EXPECT_GE(std::abs(std::atan2(q.x, q.z)), kPi / 2 - slack);
    EXPECT_NEAR(std::hypot(q.x, q.z), w / kPi, 0.5);
  }
  // So each side seam starts closed: its two edges' corners meet.
  const PieceMesh& front = m->pieces[0];
  const PieceMesh& back = m->pieces[1];
  const Vec3 front_right_hem = x[0][front.edge_vertices[1].front()];
  const Vec3 back_left_hem = x[1][back.edge_vertices[3].back()];
  EXPECT_LT(norm(front_right_hem - back_left_hem), 2.0);
}

}  // namespace
}  // namespace tp::geometry
