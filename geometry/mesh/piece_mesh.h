// geometry/mesh/piece_mesh.h: a piece triangulated in its own 2D frame (mm).
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// Triangulation of one piece's seam-line outline.
struct PieceMesh {
  std::vector<Vec2> vertices_mm;                ///< #V piece-local positions
  std::vector<std::array<int, 3>> triangles;    ///< #F counter-clockwise vertex indices
  /// For each outline edge, the indices of the vertices on it from its start to its end
  /// (inclusive); consecutive edges share their corner vertex.
  std::vector<std::vector<int>> edge_vertices;
};

}  // namespace tp::geometry
