// geometry/nesting/internal/poles.h: "poles", disjoint inscribed circles that stand in for a
// polygon's interior when measuring how deeply two items overlap.
#pragma once

#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry::nesting {

struct Circle {
  Vec2 c;
  double r = 0;
};

/// When to stop adding poles: at most `max_poles`, and fewer once they cover enough of the area
/// (`enough_at[k]` poles suffice at a coverage of `coverage[k]`).
struct PoleLimits {
  int max_poles = 48;
  int enough_at[2] = {16, 8};
  double coverage[2] = {0.8, 0.9};
};

/// Largest circle inside `ccw` (a simple counter-clockwise polygon) that overlaps none of `taken`,
/// found by a best-first quadtree search to a precision of `precision_mm`. Radius 0 if none.
[[nodiscard]] Circle largest_free_circle(const Polygon& ccw, const std::vector<Circle>& taken,
                                         double precision_mm);

/// Poles of `ccw`, largest first (the first is the pole of inaccessibility).
[[nodiscard]] std::vector<Circle> compute_poles(const Polygon& ccw, const PoleLimits& limits = {});

/// Distance from `p` to the nearest edge of `poly`.
[[nodiscard]] double distance_to_boundary(const Polygon& poly, Vec2 p);

}  // namespace tp::geometry::nesting
