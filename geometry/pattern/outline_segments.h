// geometry/pattern/outline_segments.h: building a piece's named edges from a closed chain of drawn segments.
#pragma once

#include <vector>

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// One drawn segment of a closed outline (a line, Bezier or arc, already flattened), in order;
/// each ends where the next starts. `corner_before` forces an edge to start at this segment
/// (DXF turn points); otherwise corners are found from the turning angle.
struct OutlineSegment {
  Edge edge;
  bool corner_before = false;
};

/// Joins consecutive segments into edges between corners: a corner is where the direction turns
/// by more than `corner_angle_deg` (if `detect_angles`) or a segment says corner_before. The first
/// edge starts at the first corner; with no corner at all the outline is one edge starting at the
/// first segment. Zero-length segments are dropped. Joined edges keep an exact curve when they
/// can (joined_edges). Edges are named "e0", "e1", ... in order.
std::vector<Edge> edges_from_segments(std::vector<OutlineSegment> segments, double corner_angle_deg,
                                      bool detect_angles = true);

/// Direction of travel at the start (at_end = false) or end of a flattened edge, measured over a
/// short stretch so flattening noise does not count as a turn; zero for a zero-length edge.
Vec2 edge_end_direction(const Edge& edge, bool at_end);

}  // namespace tp::geometry
