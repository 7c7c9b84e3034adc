// geometry/nesting/internal/shape_prep.h: turning an item outline into its collision outline:
// clean it, grow it by the clearance, and simplify it without ever cutting into it.
#pragma once

#include <string_view>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry::nesting {

/// Removes repeated and collinear vertices (and a closing repeat of the first), orients the outline
/// counter-clockwise and checks it is a simple polygon with positive area.
/// Fails with kInvalidPattern naming `what` when it is not.
[[nodiscard]] Result<Polygon> clean_polygon(const Polygon& outline, std::string_view what);

/// The outline grown by `radius_mm` in every direction (Minkowski sum with a regular polygon of
/// `segments` sides circumscribing the disc of that radius, so the result contains every point
/// within radius_mm of the outline). Holes the growth closes are dropped. `ccw` must be simple and
/// counter-clockwise; radius_mm > 0.
[[nodiscard]] Polygon inflate_polygon(const Polygon& ccw, double radius_mm, int segments);

/// Fewer vertices, never inward: removes reflex vertices and replaces pairs of convex vertices by
/// the meeting point of their neighbouring edges while the added area stays within
/// `max_added_area_mm2` and the outline stays simple. The result contains `ccw`.
[[nodiscard]] Polygon simplify_outward(const Polygon& ccw, double max_added_area_mm2);

}  // namespace tp::geometry::nesting
