// tests/host/pipeline/order_reprojection_test.cpp: the base size's design carried onto other
// sizes through their dress forms.
#include "host/pipeline/order_reprojection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/body/dress_form.h"
#include "geometry/samples/sizes.h"

namespace tp::host {
namespace {

geometry::BodyMeasurements size(const char* s) { return *geometry::samples::standard_size(s); }

TEST(OrderReprojection, TheBustPointLandsOnEachSizesBustPointAtTheSameOffset) {
  for (const char* target : {"S", "M", "L"}) {
    const SizeMapping map(size("M"), size(target), false);
    const geometry::Vec3 base = centre_front_bust_point(size("M"));
    const geometry::Vec3 want = centre_front_bust_point(size(target));
    EXPECT_LT(geometry::norm(map.map_point(base) - want), 1e-6) << target;
    // 30 mm in front of the bust point stays 30 mm in front of it.
    const geometry::Vec3 off{0, 0, 30};
    EXPECT_LT(geometry::norm(map.map_point(base + off) - (want + off)), 1e-6) << target;
  }
  // The sizes really differ there.
  EXPECT_GT(geometry::norm(centre_front_bust_point(size("L")) - centre_front_bust_point(size("S"))), 20);
}

TEST(OrderReprojection, TheHipPointLandsOnEachSizesHipPointAtTheSameOffset) {
  for (const char* target : {"S", "M", "L"}) {
    const SizeMapping map(size("M"), size(target), false);
    const geometry::Vec3 base = centre_front_hip_point(size("M"));
    const geometry::Vec3 want = centre_front_hip_point(size(target));
    EXPECT_NEAR(base.y, geometry::dress_form_landmarks(size("M")).hip_y, 1e-9);
    const geometry::Vec3 off{0, 0, 20};
    EXPECT_LT(geometry::norm(map.map_point(base + off) - (want + off)), 1e-6) << target;
  }
  EXPECT_GT(geometry::norm(centre_front_hip_point(size("L")) - centre_front_hip_point(size("S"))), 20);
}

TEST(OrderReprojection, LandmarkHeightsMapOntoEachOtherAndStayInOrder) {
  const SizeMapping map(size("M"), size("L"), false);
  const auto& b = map.base_landmarks();
  const auto& t = map.target_landmarks();
  EXPECT_NEAR(map.map_height_mm(b.waist_y), t.waist_y, 1e-9);
  EXPECT_NEAR(map.map_height_mm(b.hip_y), t.hip_y, 1e-9);
  EXPECT_NEAR(map.map_height_mm(b.nape_y), t.nape_y, 1e-9);
  double last = -1e9;
  for (double y = 0; y < 1800; y += 10) {
    EXPECT_GT(map.map_height_mm(y), last);
    last = map.map_height_mm(y);
  }
}

TEST(OrderReprojection, BodyPlacementKeepsSizesGradedScalesThem) {
  DesignLayerSpec planar;
  planar.type = "planar";
  const geometry::Vec3 bp = centre_front_bust_point(size("M"));
  planar.centre_mm = {bp.x, bp.y, bp.z + 20};
  planar.width_mm = 120;
  DesignLayerSpec stroke;
  stroke.type = "stroke";
  stroke.radius_mm = 8;
  stroke.points_mm = {{150, 1100, 100}, {200, 1080, 0}, {150, 1060, -100}};
  DesignLayerSpec cyl;
  cyl.type = "cylindrical";
  cyl.tile_width_mm = 200;
  cyl.axis_origin_mm = std::array<double, 3>{0, 1000, 0};
  const std::vector<DesignLayerSpec> layers{planar, stroke, cyl};

  const auto body = reproject_layers(layers, SizeMapping(size("M"), size("L"), false));
  EXPECT_DOUBLE_EQ(body[0].width_mm, 120);
  EXPECT_DOUBLE_EQ(body[1].radius_mm, 8);
  EXPECT_DOUBLE_EQ(body[2].tile_width_mm, 200);
  const geometry::Vec3 lbp = centre_front_bust_point(size("L"));
  EXPECT_NEAR(body[0].centre_mm[2], lbp.z + 20, 1e-6);
  // A bigger body: the side-seam stroke moves outwards, in its order.
  EXPECT_GT(body[1].points_mm[1][0], 200);
  EXPECT_GT(body[1].points_mm[0][2], 0);
  EXPECT_LT(body[1].points_mm[2][2], 0);

  const SizeMapping graded_map(size("M"), size("L"), true);
  const auto graded = reproject_layers(layers, graded_map);
  const double s = graded_map.girth_ratio(planar.centre_mm[1]);
  EXPECT_GT(s, 1.05);
  EXPECT_NEAR(graded[0].width_mm, 120 * s, 1e-9);
  EXPECT_GT(graded[1].radius_mm, 8);
  EXPECT_GT(graded[2].tile_width_mm, 200);
}

double polyline_mm(const std::vector<std::array<double, 3>>& pts) {
  double len = 0;
  for (size_t k = 1; k < pts.size(); ++k)
    len += std::hypot(pts[k][0] - pts[k - 1][0], pts[k][1] - pts[k - 1][1], pts[k][2] - pts[k - 1][2]);
  return len;
}

TEST(OrderReprojection, AStrokeKeepsItsLengthOnTheBodyAndStillCrossesTheSide) {
  DesignLayerSpec stroke;
  stroke.type = "stroke";
  // Around the left side at the waist, on the surface of M (1 mm out).
  const SizeMapping m_to_m(size("M"), size("M"), false);
  const double y = m_to_m.base_landmarks().waist_y + 50;
  const geometry::TorsoSection sec = geometry::dress_form_section(size("M"), y);
  for (double t = -0.6; t <= 0.61; t += 0.2) {
    const double x = sec.half_width_mm * std::cos(t) + 1, z = sec.centre_z_mm + 0.9 * sec.front_mm * std::sin(t);
    stroke.points_mm.push_back({x, y + 40 * t, z});
  }
  const double base_len = polyline_mm(stroke.points_mm);
  for (const char* target : {"S", "L"}) {
    const SizeMapping map(size("M"), size(target), false);
    const auto out = reproject_layers({stroke}, map)[0].points_mm;
    EXPECT_NEAR(polyline_mm(out) / base_len, 1.0, 0.02) << target;
    // Front half stays in front, back half behind, the middle on the side of the target's section.
    EXPECT_GT(out.back()[2], out.front()[2]);
    const geometry::TorsoSection ts = geometry::dress_form_section(size(target), out[out.size() / 2][1]);
    EXPECT_NEAR(out[out.size() / 2][0], ts.half_width_mm + 1, 2.0) << target;
  }
  // Graded, the stroke grows with the body.
  const auto graded = reproject_layers({stroke}, SizeMapping(size("M"), size("L"), true))[0].points_mm;
  EXPECT_GT(polyline_mm(graded), base_len * 1.03);
}

}  // namespace
}  // namespace tp::host
