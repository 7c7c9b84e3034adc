// geometry/design/fit_cylinder.h: the cylinder fitted closely around a garment for cylindrical
// projection (paper section 3.5.2).
#pragma once

#include <optional>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// A finite cylinder: axis through `origin_mm` along unit `direction`, radius, and the extent of
/// the fitted points along the axis (heights measured from origin_mm).
struct Cylinder {
  Vec3 origin_mm;
  Vec3 direction{0, 1, 0};
  double radius_mm = 0;
  double min_height_mm = 0;
  double max_height_mm = 0;
};

/// Smallest cylinder with axis direction `direction` containing `points_mm`: the axis passes
/// through the centre of the minimum enclosing circle of the points projected on the plane
/// normal to the axis (Welzl's algorithm, deterministic order). With `origin_mm` given the axis
/// is fixed there and only the radius is fitted. An empty point set gives radius 0.
/// @param direction  any non-zero vector (normalised here); zero falls back to +y
Cylinder fit_cylinder(const std::vector<Vec3>& points_mm, Vec3 direction, std::optional<Vec3> origin_mm = std::nullopt);

}  // namespace tp::geometry
