// tests/geometry/garment/role_placement_test.cpp: a dress form's landmarks put the arm's axis on its arm.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/body/dress_form.h"
#include "geometry/garment/role_placement.h"
#include "geometry/samples/garments.h"

namespace tp::geometry {
namespace {

class RolePlacementArm : public ::testing::TestWithParam<double> {};

// Arms at 45 and 30 degrees are apart from the torso 200 mm under the shoulders; at 25 degrees
// they are not, and the slices go lower until they find them (before, the axis fell back to 45
// degrees and the sleeves were placed beside the arm).
TEST_P(RolePlacementArm, ArmAxisFollowsTheDressFormsArm) {
  BodyMeasurements m;
  m.arm_angle_deg = GetParam();
  auto body = samples::make_dress_form_sdf(m);
  ASSERT_TRUE(body) << body.error().message;
  const BodyLandmarks L = find_landmarks(**body);
  const DressFormLandmarks form = dress_form_landmarks(m);
  for (int side : {1, -1}) {
    const Vec3 dir = side > 0 ? L.arm_dir_l : L.arm_dir_r;
    const Vec3 truth{side * form.arm_direction_left.x, form.arm_direction_left.y, form.arm_direction_left.z};
    EXPECT_GT(dot(dir, truth), std::cos(3 * std::numbers::pi / 180)) << side;
    // 500 mm down the axis from the sleeve cap's top, the axis is still deep inside the arm (its
    // radius there is about 28 mm; the SDF answers -16 mm, its band, for anything deeper).
    const Vec3 top = side > 0 ? L.arm_top_l : L.arm_top_r;
    const BodySdf::Hit h = (*body)->query(top + dir * 500);
    EXPECT_LT(h.distance_mm, -15) << side;
  }
}

INSTANTIATE_TEST_SUITE_P(ArmAngles, RolePlacementArm, ::testing::Values(45.0, 30.0, 25.0));

}  // namespace
}  // namespace tp::geometry
