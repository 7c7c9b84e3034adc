// tests/geometry/body/body_test.cpp: measurements, dress form, body OBJ reader and body SDF.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "geometry/body/body_sdf.h"
#include "geometry/body/dress_form.h"
#include "geometry/body/load_body_obj.h"
#include "geometry/body/marching_tetrahedra.h"
#include "geometry/body/measurements.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

// Girth of the body at height y: rays from the vertical axis to the surface, joined.
double girth_at(const BodySdf& sdf, double y) {
  double per = 0;
  Vec3 prev{};
  for (int a = 0; a <= 720; ++a) {
    double th = a * std::numbers::pi / 360, r = 0;
    while (r < 500 && sdf.query({r * std::sin(th), y, r * std::cos(th)}).distance_mm < 0) r += 0.25;
    Vec3 q{r * std::sin(th), y, r * std::cos(th)};
    if (a) per += norm(q - prev);
    prev = q;
  }
  return per;
}

// Each undirected edge of a closed manifold mesh is used by exactly two triangles, once each way.
bool closed_and_oriented(const BodyMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed)
    if (n != 1 || directed.count({e.second, e.first}) == 0) return false;
  return true;
}

TEST(Measurements, ValidateNamesTheField) {
  BodyMeasurements m;
  EXPECT_TRUE(validate(m));
  m.waist_mm = 1200;
  auto s = validate(m);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("waist_mm"), std::string::npos) << s.error().message;
  m = {};
  m.neck_mm = -3;
  s = validate(m);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("neck_mm -3"), std::string::npos) << s.error().message;
  // An armpit at the bust's height: the form's sections would run out of order.
  m = {};
  m.armscye_depth_mm = 0.6 * m.back_length_mm;
  s = validate(m);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("armscye_depth_mm"), std::string::npos) << s.error().message;
}

TEST(Measurements, ParseOverridesAndRejectsBadText) {
  auto m = parse_measurements("bust=960,waist_mm=770", BodyMeasurements{});
  ASSERT_TRUE(m) << m.error().what();
  EXPECT_EQ(m->bust_mm, 960);
  EXPECT_EQ(m->waist_mm, 770);
  EXPECT_EQ(m->hips_mm, BodyMeasurements{}.hips_mm);
  auto bad = parse_measurements("bust=9x0", BodyMeasurements{});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("'bust'"), std::string::npos);
  bad = parse_measurements("shoe=38", BodyMeasurements{});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("unknown measurement 'shoe'"), std::string::npos);
  bad = parse_measurements("bust", BodyMeasurements{});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kParse);
}

TEST(DressForm, ClosedMeshWhoseGirthsMatchTheMeasurements) {
  BodyMeasurements m;
  auto mesh = make_dress_form(m, DressFormOptions{.grid_spacing_mm = 8});
  ASSERT_TRUE(mesh) << mesh.error().what();
  EXPECT_TRUE(closed_and_oriented(*mesh));
  auto sdf = BodySdf::build(*mesh);
  ASSERT_TRUE(sdf);
  DressFormLandmarks l = dress_form_landmarks(m);
  // The tape goes round the convex hull; at waist and hip the section is convex. 2 % budget
  // covers the marching-tetrahedra facets (cells of 8 mm).
  EXPECT_NEAR(girth_at(*sdf, l.waist_y), m.waist_mm, 0.02 * m.waist_mm);
  EXPECT_NEAR(girth_at(*sdf, l.hip_y), m.hips_mm, 0.02 * m.hips_mm);
  Box3 b = bounds(*mesh);
  EXPECT_NEAR(b.max.y, l.nape_y + 95, 10);
  EXPECT_LT(b.min.y, l.knee_y);
  // Arms reach out: the form is wider than the shoulders.
  EXPECT_GT(b.max.x, m.shoulder_width_mm / 2 + 100);
  EXPECT_NEAR(b.max.x, -b.min.x, 2);
}

TEST(DressForm, RejectsInvalidMeasurements) {
  BodyMeasurements m;
  m.hips_mm = 0;
  auto mesh = make_dress_form(m);
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("hips_mm"), std::string::npos);
}

TEST(BodyObj, ParsesFacesOfEveryForm) {
  const char* text =
      "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2/1/1 3/1/1\nf 1//1 3//1 4//1\nf -4 -2 -1\n";
  auto m = parse_body_obj(text, 1000, "cube.obj");
  ASSERT_TRUE(m) << m.error().what();
  ASSERT_EQ(m->vertices_mm.size(), 4u);
  ASSERT_EQ(m->triangles.size(), 3u);
  EXPECT_EQ(m->vertices_mm[2].x, 1000);
  EXPECT_EQ((m->triangles[2]), (std::array<int, 3>{0, 2, 3}));
}

TEST(BodyObj, ErrorsNameFileAndLine) {
  auto m = parse_body_obj("v 0 0 0\nv 1 0\n", 1, "body.obj");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("body.obj:2"), std::string::npos) << m.error().message;
  m = parse_body_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", 1, "body.obj");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("body.obj:4: vertex index 7 out of range"), std::string::npos) << m.error().message;
  m = parse_body_obj("v 0 0 0\n", 1, "empty.obj");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("no faces"), std::string::npos);
  auto missing = load_body_obj("/nonexistent/body.obj", 1);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::kIo);
}

TEST(BodyObj, ReadsTheGarmentCodeBodyInMetres) {
  auto m = load_body_obj((test::shared_data_dir() / "garmentcode/bodies/mean_female.obj").string(), 1000);
  ASSERT_TRUE(m) << m.error().what();
  EXPECT_EQ(m->vertices_mm.size(), 23752u);
  EXPECT_EQ(m->triangles.size(), 47500u);
  Box3 b = bounds(*m);
  EXPECT_NEAR(b.max.y - b.min.y, 1662, 5);
}

// A sphere of radius 100 mm from an analytic field: distances are known everywhere.
BodyMesh sphere_mesh(double r, double h) {
  ScalarGrid g;
  g.spacing_mm = h;
  g.origin_mm = {-r - 3 * h, -r - 3 * h, -r - 3 * h};
  g.nx = g.ny = g.nz = static_cast<int>(std::ceil(2 * (r + 3 * h) / h)) + 1;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        g.values.push_back(static_cast<float>(norm(g.origin_mm + Vec3{double(i), double(j), double(k)} * h) - r));
  return marching_tetrahedra(g);
}

TEST(BodySdf, SignedDistanceToASphere) {
  BodyMesh mesh = sphere_mesh(100, 4);
  ASSERT_TRUE(closed_and_oriented(mesh));
  auto sdf = BodySdf::build(mesh, 6, 3);
  ASSERT_TRUE(sdf) << sdf.error().what();
  // Facets of a 4 mm grid lie within about 0.1 mm of the sphere.
  for (double d : {-12.0, -3.0, -0.8, 0.8, 3.0, 12.0})
    for (Vec3 dir : {Vec3{1, 0, 0}, Vec3{0, -1, 0}, normalized(Vec3{1, 2, -2}), normalized(Vec3{-3, 1, 1})}) {
      BodySdf::Hit h = sdf->query(dir * (100 + d));
      ASSERT_TRUE(h.near);
      EXPECT_NEAR(h.distance_mm, d, 0.25) << "offset " << d;
      EXPECT_GT(dot(h.normal, dir), 0.95);
      EXPECT_NEAR(sdf->approx_distance_mm(dir * (100 + d)), d, 1.5);
    }
  // Far away: a bound only, with the right sign.
  EXPECT_GE(sdf->query({0, 0, 0}).distance_mm, -1e9);
  EXPECT_LT(sdf->query({0, 0, 0}).distance_mm, 0);
  EXPECT_GT(sdf->query({400, 0, 0}).distance_mm, 0);
}

TEST(BodySdf, RejectsAnEmptyMesh) {
  auto sdf = BodySdf::build(BodyMesh{});
  ASSERT_FALSE(sdf);
  EXPECT_EQ(sdf.error().code, ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace tp::geometry
