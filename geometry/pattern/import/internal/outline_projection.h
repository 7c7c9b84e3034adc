// geometry/pattern/import/internal/outline_projection.h: the nearest point of a piece's outline,
// which the DXF and SVG importers use to put notches and marks on edges.
#pragma once

#include <limits>

#include "geometry/common/vec.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// Closest point of the outline to a point: (edge, arc length along it, distance).
struct Projection {
  int edge = -1;
  double position_mm = 0;
  double distance_mm = std::numeric_limits<double>::infinity();
};

/// The point of `piece`'s edges nearest to `at` (the first edge wins a tie).
[[nodiscard]] Projection project(const Piece& piece, Vec2 at);

/// Distance of `x` from the infinite line through p and q.
[[nodiscard]] double distance_to_line(Vec2 x, Vec2 p, Vec2 q);

}  // namespace tp::geometry::internal
