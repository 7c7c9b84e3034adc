// tests/geometry/sewing/drape_garment_test.cpp: the XPBD drape: bending gradients, strain limiting,
// a sheet draped over a capped cylinder (contact, folds without self-intersection, a plain seam's
// length, determinism).
#include "geometry/sewing/drape_garment.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <numbers>

#include "../garment/tube_fixture.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/sewing/internal/cloth_model.h"
#include "geometry/sewing/internal/xpbd_solver.h"
#include "sheet_fixture.h"

namespace tp::geometry {
namespace {

using test_fixture::flat_sheet;

TEST(DrapeGarment, DihedralGradientMatchesFiniteDifferences) {
  std::vector<Vec3> x = {{0, 0, 0}, {10, 1, 0}, {4, 8, 1}, {5, -7, 3}};
  internal::BendStencil s{.a = 0, .b = 1, .c = 2, .d = 3};
  std::array<Vec3, 4> g;
  internal::dihedral_angle(x, s, &g);
  const double h = 1e-6;
  for (int v = 0; v < 4; ++v)
    for (int k = 0; k < 3; ++k) {
      auto xp = x, xm = x;
      double* cp = &xp[v].x + k;
      double* cm = &xm[v].x + k;
      *cp += h, *cm -= h;
      const double fd = (internal::dihedral_angle(xp, s, nullptr) - internal::dihedral_angle(xm, s, nullptr)) / (2 * h);
      EXPECT_NEAR((&g[v].x)[k], fd, 1e-6) << "vertex " << v << " axis " << k;
    }
  // Flat and consistently wound: angle 0.
  std::vector<Vec3> flat = {{0, 0, 0}, {10, 0, 0}, {5, 5, 0}, {5, -5, 0}};
  EXPECT_NEAR(internal::dihedral_angle(flat, s, nullptr), 0, 1e-12);
}

TEST(DrapeGarment, TriangleProjectionLimitsStrain) {
  internal::RestTriangle t;
  t.v = {0, 1, 2};
  const Vec2 r[3] = {{0, 0}, {10, 0}, {0, 10}};
  const Vec2 c = (r[0] + r[1] + r[2]) / 3.0;
  for (int k = 0; k < 3; ++k) t.rest_mm[k] = r[k] - c;
  t.dm_inv[0][0] = 0.1, t.dm_inv[0][1] = 0, t.dm_inv[1][0] = 0, t.dm_inv[1][1] = 0.1;
  std::vector<double> w(3, 1.0);
  // Stretched 20 % along x, sheared: after one projection with stiffness ~0 only the limit acts.
  std::vector<Vec3> x = {{0, 0, 0}, {12, 0, 0}, {1, 0, 10}};
  internal::project_triangle(t, w, 0.03, 1e-9, x);
  EXPECT_NEAR(norm(x[1] - x[0]), 10.3, 0.05);
  std::vector<Vec3> y = {{0, 0, 0}, {12, 0, 0}, {1, 0, 10}};
  internal::project_triangle(t, w, 0.03, 1.0, y);
  EXPECT_NEAR(norm(y[1] - y[0]), 10, 1e-9);
  EXPECT_NEAR(norm(y[2] - y[0]), 10, 1e-9);
  EXPECT_NEAR(dot(y[1] - y[0], y[2] - y[0]), 0, 1e-9);
}

TEST(DrapeGarment, UnknownMaterialIsNamed) {
  auto m = cloth_material_preset("tweed");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("'tweed'"), std::string::npos);
  EXPECT_NE(m.error().message.find("silk-satin"), std::string::npos);
  for (const auto& name : cloth_material_names()) EXPECT_TRUE(cloth_material_preset(name)) << name;
}

TEST(DrapeGarment, SheetDrapesOverCylinderWithoutPassingThroughItself) {
  const BodySdf body = test_fixture::cylinder_body(100, 100, 400);
  const Garment sheet = flat_sheet(500, 40, 410);
  DrapeOptions o;
  o.material = *cloth_material_preset("silk-satin");
  DrapeStats st;
  auto g = drape_garment(sheet, body, o, &st);
  ASSERT_TRUE(g) << g.error().message;
  // Corners fell over the edge of the cap; the centre rests on it; nothing inside or tangled.
  EXPECT_LT(g->vertices_mm[0].y, 340);
  const Vec3 centre = g->vertices_mm[20 * 41 + 20];
  EXPECT_NEAR(centre.y, 400 + o.clearance_mm, 1.0);
  int inside = 0;
  for (const Vec3& p : g->vertices_mm) inside += body.query(p).distance_mm < 0;
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(count_self_intersections(*g), 0);
  EXPECT_GT(st.body_contacts, 0);
  // Strain: edges stay near the material's 2 % limit except at the cap's sharp rim (measured:
  // 1.8 % of edge checks beyond 5 % strain, the worst 30 %, all over the rim).
  int over = 0, checked = 0;
  for (const auto& t : g->pieces[0].mesh.triangles)
    for (int k = 0; k < 3; ++k, ++checked) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double rest = norm(g->pieces[0].mesh.vertices_mm[a] - g->pieces[0].mesh.vertices_mm[b]);
      const double now = norm(g->vertices_mm[a] - g->vertices_mm[b]);
      over += std::abs(now / rest - 1) > 0.05;
    }
  EXPECT_LT(over, checked * 0.03) << over << " of " << checked << " edge checks beyond 5 % strain";
}

TEST(DrapeGarment, SheetOnACapSettlesBeforeTheTimeLimit) {
  // A sheet laid on a capped cylinder hangs over the rim and the settle test stops it before a
  // 3 s limit (the old test, all but 0.5 % of the vertices slower than 4 mm/s in one substep,
  // ran every garment to its limit). Its corners keep folding slowly (RMS 5.5 mm/s at 3 s), so
  // the test asks for 10 mm/s. Measured: it stops at 2.45 s with the drape's 1.25 ms substeps,
  // at 1.6 s with 2.5 ms ones (coarser steps damp more); 2.85 s since the bending runs in blocks
  // of stencils (another Gauss-Seidel order: the corners' slow folding dips under 10 mm/s later).
  const BodySdf body = test_fixture::cylinder_body(100, 100, 400);
  const Garment sheet = flat_sheet(300, 20, 410);
  DrapeOptions o;
  o.duration_s = 3;
  o.settle_speed_mm_s = 10;
  DrapeStats st;
  auto g = drape_garment(sheet, body, o, &st);
  ASSERT_TRUE(g) << g.error().what();
  EXPECT_TRUE(st.settled);
  EXPECT_LT(st.simulated_s, 2.95);
  EXPECT_LT(st.settle_speed_mm_s, o.settle_speed_mm_s);
  int inside = 0;
  for (const Vec3& p : g->vertices_mm) inside += body.query(p).distance_mm < 0;
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(count_self_intersections(*g), 0);
}

// Two pieces sewn along x = 0 (their seam line's 3D vertices shared), laid over the cap so the
// seam runs across its top and down over the rim, where contact with friction holds the cloth.
TEST(DrapeGarment, PlainSeamOverTheBodyKeepsItsLength) {
  const BodySdf body = test_fixture::cylinder_body(100, 100, 400);
  constexpr int kCols = 12, kRows = 32;
  constexpr double kStep = 12.5;
  Garment g;
  const auto place = [&](int i, int j) { return Vec3{i * kStep, 410, kRows * kStep / 2 - j * kStep}; };
  test_fixture::add_grid_piece(g, kCols, kRows, kStep, [&](int i, int j) { return place(i - kCols, j); });
  // The right piece: its column 0 is the left piece's last column (the 3D vertices it was given
  // for that column stay in the garment, in no triangle).
  const int seam_in_left = kCols;
  test_fixture::add_grid_piece(g, kCols, kRows, kStep, [&](int i, int j) { return place(i, j); });
  GarmentPiece& right = g.pieces[1];
  for (int j = 0; j <= kRows; ++j)
    right.vertex_3d[j * (kCols + 1)] = g.pieces[0].vertex_3d[j * (kCols + 1) + seam_in_left];
  DrapeOptions o;
  auto d = drape_garment(g, body, o);
  ASSERT_TRUE(d) << d.error().message;
  double worst = 0, seam_mm = 0, rest_mm = 0;
  int on_rim = 0;
  for (int j = 0; j < kRows; ++j) {
    const Vec3 a = d->vertices_mm[right.vertex_3d[j * (kCols + 1)]];
    const Vec3 b = d->vertices_mm[right.vertex_3d[(j + 1) * (kCols + 1)]];
    worst = std::max(worst, std::abs(norm(a - b) / kStep - 1));
    seam_mm += norm(a - b);
    rest_mm += kStep;
    on_rim += std::abs(std::hypot(a.x, a.z) - 100) < 10 && std::abs(a.y - 400) < 10;
  }
  std::printf("figure seam_worst_segment_strain=%.4f seam_mm=%.2f rest_mm=%.2f segments_on_rim=%d\n", worst, seam_mm,
              rest_mm, on_rim);
  EXPECT_GT(on_rim, 0) << "the seam should cross the cap's rim";
  // Measured: the worst segment 0.01 % long, the seam 400.01 mm for 400 cut (3 of its segments
  // at the rim); without the drape's seam finish 0.07 % and 400.17 mm; with contact the last word
  // of each substep, 3.05 % and 400.51 mm.
  EXPECT_LT(worst, 0.001) << "the worst seam segment's strain";
  EXPECT_NEAR(seam_mm / rest_mm, 1, 0.0002);
  int inside = 0;
  for (const Vec3& p : d->vertices_mm) inside += body.query(p).distance_mm < 0;
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(count_self_intersections(*d), 0);
}

// A band 2 % shorter round than the cylinder it is sewn round (an upper and a lower piece joined by
// a seam that runs round the body, each closed on itself): the body holds the seam open, so the
// drape's seam finish, which brings free seams to their length, leaves this one out of the body,
// stretched to the girth at the clearance. Twelve columns: the seam's sweeps pull a coarse ring in
// quickly (a fine ring's segments point almost along it); without contact in the finish's rounds
// it ends at its cut length, 26 vertices inside the body.
TEST(DrapeGarment, SeamRoundTheBodyShorterThanItStaysOutOfTheBody) {
  const BodySdf body = test_fixture::cylinder_body(100, 100, 400);
  constexpr int kCols = 12, kUpperRows = 1, kLowerRows = 2;
  const double girth_mm = 0.98 * 2 * std::numbers::pi * 100;
  const double step = girth_mm / kCols;
  constexpr double kSeamY = 250, kPlaceR = 103;
  Garment g;
  const auto around = [&](int i, double y) {
    const double a = 2 * std::numbers::pi * i / kCols;
    return Vec3{kPlaceR * std::cos(a), y, kPlaceR * std::sin(a)};
  };
  // The lower piece's top row (j = kLowerRows) is the seam; the upper piece's row 0 is the same.
  test_fixture::add_grid_piece(g, kCols, kLowerRows, step,
                               [&](int i, int j) { return around(i, kSeamY - (kLowerRows - j) * step); });
  test_fixture::add_grid_piece(g, kCols, kUpperRows, step, [&](int i, int j) { return around(i, kSeamY + j * step); });
  GarmentPiece& lower = g.pieces[0];
  GarmentPiece& upper = g.pieces[1];
  const auto id = [&](int i, int j) { return j * (kCols + 1) + i; };
  for (int i = 0; i <= kCols; ++i) upper.vertex_3d[id(i, 0)] = lower.vertex_3d[id(i, kLowerRows)];
  // Each piece closed on itself: its last column is its first.
  for (int j = 0; j <= kLowerRows; ++j) lower.vertex_3d[id(kCols, j)] = lower.vertex_3d[id(0, j)];
  for (int j = 0; j <= kUpperRows; ++j) upper.vertex_3d[id(kCols, j)] = upper.vertex_3d[id(0, j)];
  DrapeOptions o;
  o.duration_s = 0.3;
  auto d = drape_garment(g, body, o);
  ASSERT_TRUE(d) << d.error().message;
  double seam_mm = 0;
  for (int i = 0; i < kCols; ++i)
    seam_mm += norm(d->vertices_mm[lower.vertex_3d[id(i + 1, kLowerRows)]] -
                    d->vertices_mm[lower.vertex_3d[id(i, kLowerRows)]]);
  int inside = 0;
  double nearest_mm = 1e300;
  for (const GarmentPiece& gp : d->pieces)
    for (int v : gp.vertex_3d) {
      const double dist = body.query(d->vertices_mm[v]).distance_mm;
      inside += dist < 0;
      nearest_mm = std::min(nearest_mm, dist);
    }
  std::printf("figure seam_mm=%.2f cut_mm=%.2f inside=%d nearest_mm=%.2f\n", seam_mm, girth_mm, inside, nearest_mm);
  EXPECT_EQ(inside, 0);
  // Held open by the body at the clearance (the body's facets are chords of the circle).
  EXPECT_GT(seam_mm / girth_mm, 1.03) << "the seam should stay stretched round the body";
  EXPECT_EQ(count_self_intersections(*d), 0);
}

TEST(DrapeGarment, SameInputSameOutputToTheBitForAnyThreadCount) {
  const BodySdf body = test_fixture::cylinder_body(100, 100, 400);
  const Garment sheet = flat_sheet(400, 24, 410);
  DrapeOptions o;
  o.duration_s = 0.3;
  o.threads = 1;
  auto a = drape_garment(sheet, body, o);
  o.threads = 2;
  auto b = drape_garment(sheet, body, o);
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->vertices_mm.size(), b->vertices_mm.size());
  EXPECT_EQ(std::memcmp(a->vertices_mm.data(), b->vertices_mm.data(), a->vertices_mm.size() * sizeof(Vec3)), 0);
}

}  // namespace
}  // namespace tp::geometry
