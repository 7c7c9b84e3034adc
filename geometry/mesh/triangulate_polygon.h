// geometry/mesh/triangulate_polygon.h: constrained Delaunay meshing of one piece's sampled outline.
#pragma once

#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/mesh/piece_mesh.h"

namespace tp::geometry {

/// Quality and size of the triangles inside a piece.
struct TriangulateOptions {
  double target_edge_mm = 20;   ///< upper bound on interior edge length, mm
  double min_angle_deg = 20.7;  ///< Delaunay refinement angle bound (CGAL B = 0.125)
  int smoothing_iterations = 8; ///< Lloyd iterations on interior vertices (0: none)
};

/// Triangulates the polygon `ring_mm` (closed, no repeated point, either orientation) with a
/// constrained Delaunay triangulation refined to `options` (CGAL Mesh_2 without boundary
/// splitting, then Lloyd smoothing of the interior). The ring's points are the first
/// vertices of the result, in order, and no other vertex lies on the boundary. Triangles are
/// counter-clockwise. edge_vertices is left empty. Fails with kMeshing on fewer than 3
/// points, duplicate points or a self-intersecting ring.
[[nodiscard]] Result<PieceMesh> triangulate_polygon(const std::vector<Vec2>& ring_mm, const TriangulateOptions& options);

}  // namespace tp::geometry
