// geometry/design/internal/band_mesh.h: triangles filling the allowance band between a piece's
// seam-line boundary and its cut outline.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// Triangulates the region inside `outer` and outside `inner` (simple polygons, any orientation;
/// `inner` inside `outer`, possibly sharing boundary parts). Constrained Delaunay with exact
/// intersections, so touching or overlapping boundaries are fine. Triangles are counter-clockwise.
std::vector<std::array<Vec2, 3>> triangulate_band(const Polygon& inner, const Polygon& outer);

/// Even-odd point in polygon test.
bool inside_polygon(const Polygon& poly, Vec2 p);

}  // namespace tp::geometry::internal
