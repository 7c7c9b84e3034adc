// tests/geometry/garment/fit_checks_test.cpp: fit checks pass a sewn tube and fail it off the body, unsewn or tangled; alignment.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/body/body_sdf.h"
#include "geometry/body/marching_tetrahedra.h"
#include "geometry/garment/align_to_body.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/sewing/sew_garment.h"
#include "tests/geometry/garment/tube_fixture.h"

namespace tp::geometry {
namespace {

using namespace test_fixture;

struct Sewn {
  Garment garment;
  SewStats stats;
};

Sewn sew(const Pattern& p, const BodySdf& body) {
  Sewn s;
  auto g = sew_garment(p, body, SewOptions{.target_edge_mm = 20}, &s.stats);
  EXPECT_TRUE(g) << g.error().what();
  if (g) s.garment = std::move(*g);
  return s;
}

bool failed(const FitReport& r, const std::string& check) {
  for (const auto& f : r.failures)
    if (f.check == check) return true;
  return false;
}

TEST(FitChecks, SewnTubeOnItsBodyPasses) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  Sewn s = sew(p, body);
  ASSERT_EQ(s.stats.stitch_gap_mm.size(), 2u);
  FitReport r = check_fit(p, s.garment, &body, s.stats.stitch_gap_mm);
  EXPECT_TRUE(r.pass) << (r.failures.empty() ? "" : r.failures[0].message);
  EXPECT_EQ(r.stitches, 2);
  EXPECT_LT(r.stitch_gap_max_mm, 2);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_EQ(r.inside_body, 0);
  EXPECT_EQ(r.body_crossings, 0);
  EXPECT_NEAR(r.body_distance_p50_mm, 15, 6);  // radius 115 round radius 100
  EXPECT_EQ(r.off_body, 0);
}

TEST(FitChecks, GarmentOneMetreOffTheBodyFails) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  Sewn s = sew(p, body);
  for (Vec3& v : s.garment.vertices_mm) v.x += 1000;
  FitReport r = check_fit(p, s.garment, &body, s.stats.stitch_gap_mm);
  EXPECT_FALSE(r.pass);
  EXPECT_TRUE(failed(r, "off_body"));
  EXPECT_GT(r.off_body, 0.99);
  EXPECT_GT(r.body_distance_p95_mm, 800);
  ASSERT_FALSE(r.failures.empty());
  EXPECT_NE(r.failures.back().message.find("not on the body"), std::string::npos);
  EXPECT_EQ(r.failures.back().view, "side");  // moved along x, the body's side
}

TEST(FitChecks, GarmentSewnOnTheWrongBodyFails) {
  // The tube is placed round a body at x = 0; the job's body stands 1 m to the side. Sewing
  // without alignment closes the tube in the air; the checks see it.
  BodySdf wrong = cylinder_body(100, 0, 600, 1000);
  Pattern p = tube_pattern();
  Sewn s = sew(p, wrong);
  FitReport r = check_fit(p, s.garment, &wrong, s.stats.stitch_gap_mm);
  EXPECT_FALSE(r.pass);
  EXPECT_TRUE(failed(r, "off_body"));
}

TEST(FitChecks, GarmentSewnOnASmallerBodyIsInsideTheJobsBody) {
  // Sewn on a slim body, then checked on a broader one in the same place (a job whose body
  // changed after its garment was planned): the garment is inside it.
  BodySdf slim = cylinder_body(100, 0, 600);
  BodySdf broad = cylinder_body(140, 0, 600);
  Pattern p = tube_pattern();
  Sewn s = sew(p, slim);
  ASSERT_TRUE(check_fit(p, s.garment, &slim, s.stats.stitch_gap_mm).pass);
  FitReport r = check_fit(p, s.garment, &broad, s.stats.stitch_gap_mm);
  EXPECT_FALSE(r.pass);
  EXPECT_TRUE(failed(r, "inside_body"));
  EXPECT_GT(r.inside_body, 0);
}

TEST(FitChecks, StitchGapBeyondTheLimitNamesTheStitch) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  Sewn s = sew(p, body);
  auto gaps = s.stats.stitch_gap_mm;
  gaps[1].back() = 7.5;
  FitReport r = check_fit(p, s.garment, &body, gaps);
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.worst_stitch, 1);
  EXPECT_DOUBLE_EQ(r.stitch_gap_max_mm, 7.5);
  ASSERT_TRUE(failed(r, "stitch_gap"));
  EXPECT_NE(r.failures[0].message.find("stitch 1, piece 'back' edge 'right'"), std::string::npos) << r.failures[0].message;
  // A job may allow more.
  FitLimits loose;
  loose.max_stitch_gap_mm = 10;
  EXPECT_TRUE(check_fit(p, s.garment, &body, gaps, loose).pass);
}

TEST(FitChecks, CrossingTrianglesCountNeighboursDoNot) {
  Garment g;
  GarmentPiece gp;
  // Triangle 0 in z = 0; triangle 1 pierces it; triangle 2 shares an edge with triangle 0.
  g.vertices_mm = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {2, 2, -5}, {2, 2, 5}, {4, 4, 0}, {10, 10, 0}};
  gp.mesh.vertices_mm = {{0, 0}, {1, 0}, {0, 1}, {2, 2}, {2, 3}, {3, 3}, {4, 4}};
  gp.mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {1, 6, 2}};
  gp.vertex_3d = {0, 1, 2, 3, 4, 5, 6};
  g.pieces = {gp};
  std::vector<int> per_piece;
  EXPECT_EQ(count_self_intersections(g, &per_piece), 1);
  EXPECT_EQ(per_piece[0], 2);
}

TEST(FitChecks, BodyPokingThroughATriangleFailsWithEveryVertexOutside) {
  // One flat triangle at y = 300 across a cylinder of radius 100: its three vertices are outside
  // the body (x = -300, x = 300, z = 400), its middle (z = 90 near x = 0) inside. Vertex tests
  // see nothing; the triangle crosses the body's surface.
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p;
  p.pieces = {rectangle("front", 100, 100)};
  Garment g;
  GarmentPiece gp;
  g.vertices_mm = {{-300, 300, 90}, {300, 300, 90}, {0, 300, 400}};
  gp.mesh.vertices_mm = {{0, 0}, {600, 0}, {300, 310}};
  gp.mesh.triangles = {{0, 1, 2}};
  gp.vertex_3d = {0, 1, 2};
  g.pieces = {gp};
  // Reported by default, a failure where the job limits it.
  EXPECT_TRUE(check_fit(p, g, &body, {}).pass);
  FitLimits strict;
  strict.max_body_crossings = 0;
  FitReport r = check_fit(p, g, &body, {}, strict);
  EXPECT_EQ(r.inside_body, 0);
  EXPECT_EQ(r.body_crossings, 1);
  EXPECT_EQ(count_body_crossings(g, body.mesh()), 1);
  ASSERT_TRUE(failed(r, "body_crossings"));
  EXPECT_NE(r.failures.back().message.find("piece 'front'"), std::string::npos) << r.failures.back().message;
  // Moved 200 mm out to the front it clears the body.
  for (Vec3& v : g.vertices_mm) v.z += 200;
  EXPECT_EQ(count_body_crossings(g, body.mesh()), 0);
}

TEST(AlignToBody, PatternPlacedAroundAnotherBodyIsMovedOntoThisOne) {
  // The tube was placed round a body at the origin; this body stands 1 m up and 0.5 m aside.
  BodySdf body = cylinder_body(100, 1000, 2600, 500);
  Pattern p = tube_pattern();
  auto al = align_to_body(p, body);
  ASSERT_TRUE(al) << al.error().what();
  EXPECT_TRUE(al->moved);
  EXPECT_FALSE(al->turned);
  EXPECT_NEAR(al->offset_mm.x, 500, 10);
  EXPECT_GT(al->offset_mm.y, 1000);
  EXPECT_NE(al->reason.find("did not surround"), std::string::npos) << al->reason;
  // Once aligned it surrounds the body: a second call leaves it.
  auto again = align_to_body(p, body);
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->moved);
  // And it sews onto the body.
  Sewn s = sew(p, body);
  FitReport r = check_fit(p, s.garment, &body, s.stats.stitch_gap_mm);
  EXPECT_TRUE(r.pass) << (r.failures.empty() ? "" : r.failures[0].message);
}

TEST(AlignToBody, MirroredFrameIsTurnedAndWrongUnitsRefused) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  // Mirror the frame: the front behind, the back in front.
  std::swap(p.pieces[0].placement, p.pieces[1].placement);
  auto al = align_to_body(p, body);
  ASSERT_TRUE(al);
  EXPECT_TRUE(al->turned);
  EXPECT_GT(p.pieces[0].placement->translation_mm.z, 0);

  Pattern metres = tube_pattern();
  for (Piece& pc : metres.pieces) pc.placement->translation_mm = pc.placement->translation_mm * 1000.0;
  auto bad = align_to_body(metres, body);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("other units"), std::string::npos) << bad.error().message;
}

}  // namespace
}  // namespace tp::geometry
