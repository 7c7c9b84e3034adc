// tests/geometry/garment/garment_test.cpp: sewing a tube round a cylinder, distortion figures, OBJ export.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "geometry/body/body_sdf.h"
#include "geometry/body/marching_tetrahedra.h"
#include "geometry/garment/distortion.h"
#include "geometry/garment/garment_obj.h"
#include "geometry/sewing/sew_garment.h"
#include "tests/geometry/garment/tube_fixture.h"

namespace tp::geometry {
namespace {

using namespace test_fixture;

TEST(SewGarment, TubeRoundACylinderKeepsItsShapeAndSharesSeamVertices) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  SewOptions o;
  o.target_edge_mm = 18;
  SewStats st;
  auto g = sew_garment(p, body, o, &st);
  ASSERT_TRUE(g) << g.error().what();
  ASSERT_EQ(g->pieces.size(), 2u);
  // Seam vertices are shared: fewer 3D vertices than chart vertices, by one per sewn pair.
  size_t charts = g->pieces[0].mesh.vertices_mm.size() + g->pieces[1].mesh.vertices_mm.size();
  size_t seam_pairs = g->pieces[0].mesh.edge_vertices[1].size() + g->pieces[0].mesh.edge_vertices[3].size();
  EXPECT_EQ(g->vertices_mm.size(), charts - seam_pairs);
  EXPECT_EQ(g->pieces[0].vertex_3d[g->pieces[0].mesh.edge_vertices[1].front()],
            g->pieces[1].vertex_3d[g->pieces[1].mesh.edge_vertices[3].back()]);
  DistortionReport r = measure_distortion(p, *g, &body);
  EXPECT_LT(r.strain_mean, 0.005);
  EXPECT_LT(r.strain_p95, 0.01);
  EXPECT_LT(r.seam_len_diff_max, 0.005);
  EXPECT_EQ(r.inside_body, 0);
  EXPECT_GE(r.min_clearance_mm, o.clearance_mm - 0.01);
  // The tube stays a tube of its own girth: every vertex near radius 115.
  for (const Vec3& v : g->vertices_mm) EXPECT_NEAR(std::hypot(v.x, v.z), 115, 6);
}

TEST(SewGarment, TooSmallTubeIsPushedOutAndReportsStrain) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  // Narrow both panels to a girth of 2 pi 90: it cannot close round the body unstretched.
  for (Piece& pc : p.pieces) {
    double w = kPi * 90;
    pc.edges[0].points_mm[1].x = w, pc.edges[1].points_mm = {{w, 0}, {w, 300}}, pc.edges[2].points_mm[0].x = w;
    pc.placement->translation_mm.x = pc.placement->translation_mm.x > 0 ? w / 2 : -w / 2;
  }
  auto g = sew_garment(p, body, SewOptions{.target_edge_mm = 20});
  ASSERT_TRUE(g);
  DistortionReport r = measure_distortion(p, *g, &body);
  EXPECT_EQ(r.inside_body, 0);
  EXPECT_GT(r.strain_mean, 0.08);  // stretched by about 103 / 90 - 1
  EXPECT_GT(r.area_change, 0.08);
}

TEST(Distortion, FlatAndStretchedGarments) {
  Pattern p;
  p.pieces = {rectangle("a", 100, 50)};
  Garment g;
  GarmentPiece gp;
  gp.mesh.vertices_mm = {{0, 0}, {100, 0}, {100, 50}, {0, 50}};
  gp.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  gp.mesh.edge_vertices = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  gp.vertex_3d = {0, 1, 2, 3};
  g.pieces = {gp};
  for (Vec2 v : gp.mesh.vertices_mm) g.vertices_mm.push_back({v.x, v.y, 0});
  DistortionReport r = measure_distortion(p, g, nullptr);
  EXPECT_NEAR(r.strain_mean, 0, 1e-12);
  EXPECT_NEAR(r.area_change, 0, 1e-12);
  for (Vec3& v : g.vertices_mm) v.x *= 1.1;
  r = measure_distortion(p, g, nullptr);
  EXPECT_NEAR(r.strain_mean, 0.1, 1e-9);
  EXPECT_NEAR(r.strain_p95, 0.1, 1e-9);
  EXPECT_NEAR(r.area_change, 0.1, 1e-9);
}

TEST(GarmentObj, OnePositionPerSeamVertexAndOneUvPerPiece) {
  BodySdf body = cylinder_body(100, 0, 600);
  Pattern p = tube_pattern();
  auto g = sew_garment(p, body, SewOptions{.target_edge_mm = 40, .coarse_factor = 0});
  ASSERT_TRUE(g);
  std::string obj = garment_to_obj(p, *g);
  std::istringstream in(obj);
  std::string line;
  size_t v = 0, vt = 0, f = 0, groups = 0;
  while (std::getline(in, line)) {
    v += line.rfind("v ", 0) == 0;
    vt += line.rfind("vt ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
    groups += line.rfind("g ", 0) == 0;
  }
  EXPECT_EQ(v, g->vertices_mm.size());
  EXPECT_EQ(vt, g->pieces[0].mesh.vertices_mm.size() + g->pieces[1].mesh.vertices_mm.size());
  EXPECT_EQ(f, g->pieces[0].mesh.triangles.size() + g->pieces[1].mesh.triangles.size());
  EXPECT_EQ(groups, 2u);
  EXPECT_NE(obj.find("# piece back uv_offset_mm"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
