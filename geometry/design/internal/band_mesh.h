// geometry/design/internal/band_mesh.h: triangles filling the allowance band between a piece's
// seam-line boundary and its cut outline.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// Triangulates the region inside `outer` and outside `inner` (simple polygons, any orientation;
/// `inner` inside `outer`, possibly sharing boundary parts). Constrained Delaunay with exact
/// intersections, so touching or overlapping boundaries are fine. Outer edges longer than
/// `max_edge_mm` are split first so the triangles stay small and well shaped (no slivers running
/// the length of a seam). Triangles are counter-clockwise.
/// `cuts` are extra segments the triangles must not cross (where the allowance's print source
/// changes abruptly, e.g. the mitre line between a seam and a hem); parts outside the band are
/// ignored.
std::vector<std::array<Vec2, 3>> triangulate_band(const Polygon& inner, const Polygon& outer, double max_edge_mm,
                                                  const std::vector<std::array<Vec2, 2>>& cuts = {});

/// Even-odd point in polygon test.
bool inside_polygon(const Polygon& poly, Vec2 p);

}  // namespace tp::geometry::internal
