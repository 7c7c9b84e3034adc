// geometry/pattern/curve.h: edge curves (lines, Bezier chains, circular arcs) and their flattening.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Default chord tolerance: the largest distance in mm between a curve and its flattened polyline.
inline constexpr double kDefaultChordTolerance_mm = 0.05;
/// Smallest chord tolerance accepted; finer requests are clamped to it (bounds point counts).
inline constexpr double kMinChordTolerance_mm = 1e-4;
/// Most points one edge may flatten to; curves needing more are rejected as malformed.
inline constexpr size_t kMaxEdgePoints = 200000;

/// Recomputes `edge.points_mm` from `edge.curve`, `edge.control_mm` and the end points.
/// For kPolyline, the interior points already in points_mm are kept and only the ends are set.
/// Fails (kInvalidPattern) on non-finite coordinates, a malformed control list (wrong count),
/// an arc whose point-on-arc is collinear with its ends, or a curve needing more than
/// kMaxEdgePoints points.
[[nodiscard]] Status flatten_edge(Edge& edge, Vec2 start_mm, Vec2 end_mm,
                                  double chord_tolerance_mm = kDefaultChordTolerance_mm);

/// A straight edge from `a_mm` to `b_mm`.
Edge make_line_edge(std::string name, Vec2 a_mm, Vec2 b_mm);

/// Centre of the circle through three points; nullopt when they are (nearly) collinear.
std::optional<Vec2> circle_centre(Vec2 a, Vec2 b, Vec2 c);

/// The edge run backwards: points, Bezier chain and arc kept exact.
Edge reversed_edge(const Edge& edge);

/// The edge mapped by an affine map (points and control points; exact for lines, Beziers and,
/// when `map` is a similarity, arcs).
Edge transformed_edge(const Edge& edge, const Affine2& map);

/// A cubic chain (3n-1 controls) equal to the edge, for kLine, kQuadratic and kCubic edges;
/// nullopt for arcs and polylines.
std::optional<std::vector<Vec2>> as_cubic_chain(const Edge& edge);

/// `a` followed by `b` (a ends where b starts) as one edge named like `a`. Keeps an exact curve
/// when possible (collinear lines, arcs of one circle, Bezier chains); otherwise a polyline.
/// The result's points_mm are the two polylines joined, so no re-flattening is needed.
Edge joined_edges(const Edge& a, const Edge& b);

}  // namespace tp::geometry
