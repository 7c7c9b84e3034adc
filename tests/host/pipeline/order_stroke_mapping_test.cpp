// tests/host/pipeline/order_stroke_mapping_test.cpp: a stroke across a seam of one skirt size,
// carried through the pieces onto a larger size, still crosses that seam and grows with it.
#include "host/pipeline/order_stroke_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/geometry/design/test_garments.h"

namespace tp::host {
namespace {

using geometry::Vec3;

constexpr int kGores = 8;
const double kPi = std::numbers::pi;

// Angle around the skirt's axis, 0 at the front (+z), growing towards +x.
double angle_of(Vec3 p) { return std::atan2(p.x, p.z); }

double length_of(const std::vector<Vec3>& pts) {
  double s = 0;
  for (size_t i = 1; i < pts.size(); ++i) s += norm(pts[i] - pts[i - 1]);
  return s;
}

TEST(OrderStrokeMapping, AStrokeAcrossASeamCrossesItInTheOtherSizeAndGradesWithIt) {
  // Gore k spans angles [(2k - 1), (2k + 1)] * pi / 8: gores 0 and 1 meet at pi / 8.
  const auto small = test::gore_skirt(kGores, 120, 260, 600);
  const auto large = test::gore_skirt(kGores, 140, 310, 660);
  const double seam = kPi / kGores;
  // Five points half way down the small skirt, from gore 0's middle to gore 1's, 2 mm off it.
  std::vector<Vec3> stroke;
  for (int k = 0; k <= 4; ++k) {
    const double th = seam * (0.3 + 0.35 * k);
    const double r = 190 * std::cos(kPi / kGores) + 2;  // about on the facets at y = -300
    stroke.push_back({r * std::sin(th), -300, r * std::cos(th)});
  }
  std::string why;
  auto mapped =
      map_stroke_through_pieces(stroke, {&small.pattern, &small.garment}, {&large.pattern, &large.garment}, why);
  ASSERT_TRUE(mapped) << why;
  ASSERT_EQ(mapped->size(), stroke.size());
  EXPECT_EQ((*mapped)[0].piece, "gore0");
  EXPECT_EQ((*mapped)[4].piece, "gore1");
  std::vector<Vec3> pts;
  for (const auto& m : *mapped) pts.push_back(m.point_mm);
  // The same seam is crossed: the mapped points start before the seam's angle and end after it,
  // each at the same angle as in the small size (the gores grade evenly around the axis).
  EXPECT_LT(angle_of(pts.front()), seam);
  EXPECT_GT(angle_of(pts.back()), seam);
  for (size_t k = 0; k < pts.size(); ++k) EXPECT_NEAR(angle_of(pts[k]), angle_of(stroke[k]), 0.01) << k;
  // Half way down the large skirt (the same place in the piece), so its length grows with the
  // girth there: 225 / 190 mm of radius.
  EXPECT_NEAR(pts[2].y, -330, 1.0);
  EXPECT_NEAR(length_of(pts) / length_of(stroke), 225.0 / 190.0, 0.02);

  // The identity: the base onto itself gives the points back (on the surface plus their offset).
  auto same =
      map_stroke_through_pieces(stroke, {&small.pattern, &small.garment}, {&small.pattern, &small.garment}, why);
  ASSERT_TRUE(same) << why;
  for (size_t k = 0; k < stroke.size(); ++k) EXPECT_LT(norm((*same)[k].point_mm - stroke[k]), 1e-6) << k;
}

TEST(OrderStrokeMapping, APieceMissingInTheOtherSizeIsNamed) {
  const auto small = test::gore_skirt(kGores, 120, 260, 600);
  auto other = test::gore_skirt(kGores, 140, 310, 660);
  other.pattern.pieces[0].name = "front";
  std::string why;
  auto mapped = map_stroke_through_pieces({{0, -300, 190}}, {&small.pattern, &small.garment},
                                          {&other.pattern, &other.garment}, why);
  EXPECT_FALSE(mapped);
  EXPECT_NE(why.find("piece 'gore0'"), std::string::npos) << why;
}

}  // namespace
}  // namespace tp::host
