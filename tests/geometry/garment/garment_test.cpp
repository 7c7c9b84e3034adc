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

// A 400 x 200 mm piece meshed on a 20 mm grid, its 3D vertices numbered from first_3d.
GarmentPiece grid_piece(int first_3d) {
  GarmentPiece gp;
  const int nx = 21, ny = 11;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) gp.mesh.vertices_mm.push_back({20.0 * i, 20.0 * j});
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      gp.mesh.triangles.push_back({a, b, c});
      gp.mesh.triangles.push_back({a, c, d});
    }
  gp.mesh.edge_vertices.resize(4);
  for (int i = 0; i < nx; ++i) gp.mesh.edge_vertices[0].push_back(i);                       // hem
  for (int j = 0; j < ny; ++j) gp.mesh.edge_vertices[1].push_back(j * nx + nx - 1);         // right
  for (int i = nx - 1; i >= 0; --i) gp.mesh.edge_vertices[2].push_back((ny - 1) * nx + i);  // top
  for (int j = ny - 1; j >= 0; --j) gp.mesh.edge_vertices[3].push_back(j * nx);             // left
  for (size_t v = 0; v < gp.mesh.vertices_mm.size(); ++v) gp.vertex_3d.push_back(first_3d + static_cast<int>(v));
  return gp;
}

TEST(Distortion, TheEasedRegionsStrainAndSeamsAreReportedApart) {
  // a's hem gathered (marked, ratio 1.5) into b's top, a's top sewn plain to b's hem.
  Pattern p;
  p.pieces = {rectangle("a", 400, 200), rectangle("b", 400, 200)};
  p.stitches = {Stitch{EdgeSpan{0, 0, 0, -1}, EdgeSpan{1, 2, 0, -1}, false, 1.5},
                Stitch{EdgeSpan{0, 2, 0, -1}, EdgeSpan{1, 0, 0, -1}, false}};
  Garment g;
  g.pieces = {grid_piece(0), grid_piece(231)};
  for (const GarmentPiece& gp : g.pieces)
    for (Vec2 v : gp.mesh.vertices_mm) g.vertices_mm.push_back({v.x, v.y, 1000.0 * (g.vertices_mm.size() >= 231)});
  // a's bottom 40 mm stretched 20 % along the hem: all within 60 mm of the gathered seam.
  for (int v = 0; v < 231; ++v)
    if (g.vertices_mm[static_cast<size_t>(v)].y <= 40) g.vertices_mm[static_cast<size_t>(v)].x *= 1.2;
  const DistortionReport r = measure_distortion(p, g, nullptr);
  EXPECT_GT(r.strain_p95, 0.15);
  EXPECT_NEAR(r.strain_p95_plain, 0, 1e-12);
  EXPECT_GT(r.strain_p95_eased, 0.15);
  // Three 20 mm rows of each piece's ten have their centroids within 60 mm of the gathered seam.
  EXPECT_NEAR(r.eased_area_fraction, 0.3, 1e-9);
  ASSERT_EQ(r.seams.size(), 2u);
  EXPECT_TRUE(r.seams[0].eased);
  EXPECT_FALSE(r.seams[1].eased);
  EXPECT_NEAR(r.seam_len_diff_max, 0.2, 1e-9);
  EXPECT_NEAR(r.seam_len_diff_max_plain, 0, 1e-12);
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
