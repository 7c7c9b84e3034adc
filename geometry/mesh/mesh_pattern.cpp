// geometry/mesh/mesh_pattern.cpp: meshing of all pieces with seam-matched boundary samples.
#include "geometry/mesh/mesh_pattern.h"

#include <cmath>

#include "geometry/mesh/sample_boundary.h"

namespace tp::geometry {

Result<PatternMesh> mesh_pattern(const Pattern& pattern, const TriangulateOptions& options) {
  auto sampled = sample_boundary(pattern, options.target_edge_mm);
  if (!sampled) return std::unexpected(sampled.error().with_context("pattern '" + pattern.name + "'"));
  PatternMesh out;
  out.pieces.reserve(pattern.pieces.size());
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    auto mesh = triangulate_polygon(sampled->pieces[p].ring_mm, options);
    if (!mesh) return std::unexpected(mesh.error().with_context("piece '" + pattern.pieces[p].name + "'"));
    // The ring is the mesh's first vertices, so ring indices are mesh indices.
    mesh->edge_vertices = sampled->pieces[p].edge_vertices;
    out.pieces.push_back(std::move(*mesh));
  }
  out.stitch_vertices = std::move(sampled->stitch_pairs);
  return out;
}

double target_edge_for_vertex_count(const Pattern& pattern, int vertex_count) {
  double area = 0;
  for (const Piece& p : pattern.pieces) area += std::abs(signed_area(outline(p)));
  // Refined, smoothed Delaunay meshes average edges near 0.69 of the size bound; a vertex owns about
  // 0.87 h^2 of area for mean edge h (equilateral lattice).
  constexpr double kMeanEdgeOverBound = 0.69;
  double mean_edge = std::sqrt(area / (0.866 * std::max(vertex_count, 1)));
  return mean_edge / kMeanEdgeOverBound;
}

}  // namespace tp::geometry
