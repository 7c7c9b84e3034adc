// tests/geometry/nesting/internal/strip_frame_test.cpp: a strip placement and the roll placement it
// converts to put every piece point at the same place on the roll.
#include "geometry/nesting/internal/strip_frame.h"

#include <gtest/gtest.h>

namespace tp::geometry::nesting {
namespace {

/// What the strip engine does to a point of an item: mirror x, rotate, translate.
Vec2 strip_transform(const StripPlacement& p, Vec2 s) {
  const Affine2 m = Affine2::scale(p.mirror ? -1 : 1, 1);
  return Affine2::translation(p.translation).compose(Affine2::rotation_deg(p.rotation_deg)).compose(m).apply(s);
}

TEST(StripFrame, StripPlacementAndRollPlacementAgreeOnEveryPoint) {
  const Vec2 points[] = {{0, 0}, {120, 0}, {120, 340}, {-35.5, 80.25}};
  for (bool mirror : {false, true})
    for (double deg : {0.0, 90.0, 180.0, 270.0, 37.0, 359.5}) {
      StripPlacement p;
      p.mirror = mirror;
      p.rotation_deg = deg;
      p.translation = {812.5, 431.0};
      const PiecePlacement pp = strip_to_roll_placement(p, 3);
      EXPECT_EQ(pp.piece, 3);
      for (Vec2 q : points) {
        const Vec2 via_strip = strip_to_roll(strip_transform(p, piece_to_strip_item(q)));
        const Vec2 via_roll = pp.piece_to_roll().apply(q);
        EXPECT_NEAR(via_strip.x, via_roll.x, 1e-9) << "mirror " << mirror << " deg " << deg;
        EXPECT_NEAR(via_strip.y, via_roll.y, 1e-9) << "mirror " << mirror << " deg " << deg;
      }
    }
}

TEST(StripFrame, PoseConversionsAreInverse) {
  for (bool mirror : {false, true})
    for (double deg : {0.0, 45.0, 90.0, 180.0, 271.0}) {
      EXPECT_NEAR(strip_to_roll_deg(roll_to_strip_deg(deg, mirror), mirror), deg, 1e-9);
      const Vec2 v{3, -7};
      EXPECT_EQ(strip_to_roll(roll_to_strip(v)).x, v.x);
      EXPECT_EQ(strip_to_roll(roll_to_strip(v)).y, v.y);
    }
}

TEST(StripFrame, AnglesAreNormalisedAndSnapped) {
  EXPECT_EQ(normalise_deg(-90), 270);
  EXPECT_EQ(normalise_deg(720), 0);
  EXPECT_EQ(normalise_deg(90 + 1e-12), 90);
}

}  // namespace
}  // namespace tp::geometry::nesting
