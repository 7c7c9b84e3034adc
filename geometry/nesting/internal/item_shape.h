// geometry/nesting/internal/item_shape.h: an item's collision shape (grown, simplified, with poles)
// and that shape under one pose (mirror then rotation), ready to be translated.
#pragma once

#include <vector>

#include "geometry/common/vec.h"
#include "geometry/nesting/internal/poles.h"

namespace tp::geometry::nesting {

/// Collision shape of one item type, in the item's own frame.
struct ItemShape {
  Polygon original;            ///< cleaned input outline (counter-clockwise)
  Polygon outline;             ///< collision outline: grown by the clearance, simplified outward
  std::vector<Circle> poles;   ///< of `outline`, largest first
  double area = 0;             ///< of `original`, mm²
  double hull_area = 0;        ///< of the convex hull of `outline`
  double diameter = 0;         ///< largest distance between two vertices of `outline`
};

/// A pose: mirror x -> -x (if set), then rotate by angle_rad counter-clockwise.
struct Pose {
  int index = -1;          ///< index into the item's discrete poses; -1 for a free angle
  double angle_rad = 0;
  bool mirror = false;
};

/// An item shape under one pose, before translation.
struct OrientedShape {
  std::vector<Vec2> pts;       ///< collision outline, counter-clockwise
  std::vector<Circle> poles;
  Box2 box;                    ///< of pts
  double original_max_x = 0;   ///< largest x of the original outline in this pose
  double original_min_x = 0;
};

/// Applies a pose to an item shape.
[[nodiscard]] OrientedShape orient(const ItemShape& shape, const Pose& pose);

/// Maps a point of the item frame by a pose (no translation).
[[nodiscard]] inline Vec2 apply_pose(Vec2 p, double cos_a, double sin_a, bool mirror) {
  const double x = mirror ? -p.x : p.x;
  return {cos_a * x - sin_a * p.y, sin_a * x + cos_a * p.y};
}

/// Area of the convex hull of a point set.
[[nodiscard]] double convex_hull_area(const std::vector<Vec2>& pts);

/// Largest distance between two points of a set.
[[nodiscard]] double point_set_diameter(const std::vector<Vec2>& pts);

}  // namespace tp::geometry::nesting
