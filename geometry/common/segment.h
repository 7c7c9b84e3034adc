// geometry/common/segment.h: distance from a point to a 2D segment.
#pragma once

#include <algorithm>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// Distance from p to the segment a-b (to a when the segment is a point).
inline double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 <= 0) return norm(p - a);
  const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return norm(p - (a + ab * t));
}

}  // namespace tp::geometry
