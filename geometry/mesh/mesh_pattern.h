// geometry/mesh/mesh_pattern.h: triangulate every piece of a pattern with matched seam vertices.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/mesh/piece_mesh.h"
#include "geometry/mesh/triangulate_polygon.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Every piece meshed, plus the vertex pairs each stitch sews together.
struct PatternMesh {
  std::vector<PieceMesh> pieces;  ///< same order as Pattern::pieces, edge_vertices filled
  /// Per stitch: {vertex on piece a, vertex on piece b} pairs from span a's start to its end.
  std::vector<std::vector<std::array<int, 2>>> stitch_vertices;
};

/// Meshes each piece (sample_boundary, then triangulate_polygon with `options`): stitched spans
/// get the same number of vertices at matching arc-length positions on both sides.
/// Fails with the first piece's error, prefixed with the piece name.
[[nodiscard]] Result<PatternMesh> mesh_pattern(const Pattern& pattern, const TriangulateOptions& options);

/// Target edge length (mm) that gives roughly `vertex_count` vertices over all pieces.
double target_edge_for_vertex_count(const Pattern& pattern, int vertex_count);

}  // namespace tp::geometry
