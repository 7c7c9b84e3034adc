// geometry/pattern/internal/segment_intersection.h: finds where a closed polygon crosses itself.
#pragma once

#include <optional>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// Two segments of a polygon that meet although they are not neighbours (or neighbours that
/// fold back onto each other). Segment i runs from poly[i] to poly[(i + 1) % n].
struct SelfIntersection {
  int segment_a = 0;
  int segment_b = 0;
  Vec2 where;
};

/// The first self-intersection found, or nullopt for a simple polygon. O(n log n + k) with a
/// sweep over x; poly must have no repeated consecutive vertices.
std::optional<SelfIntersection> find_self_intersection(const std::vector<Vec2>& poly);

}  // namespace tp::geometry::internal
