// geometry/sewing/internal/self_collision.h: cloth self-collision: a spatial hash finds
// point-triangle and edge-edge pairs near each other, and a projection keeps them apart.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/common/thread_pool.h"
#include "geometry/common/vec.h"
#include "geometry/sewing/internal/cloth_model.h"

namespace tp::geometry::internal {

/// A vertex near a triangle, and the side of the triangle it was on when found.
struct PointTrianglePair {
  int vertex = 0;
  int triangle = 0;
  double side = 1;  ///< +1 on the normal's side, -1 behind
};

/// Two edges near each other, and the direction from the second to the first when found.
struct EdgeEdgePair {
  int edge_a = 0, edge_b = 0;
  Vec3 separation;  ///< unit
};

/// Candidate pairs of one broad phase.
struct SelfCollisionPairs {
  std::vector<PointTrianglePair> point_triangle;
  std::vector<EdgeEdgePair> edge_edge;
};

/// Buffers a broad phase reuses from one search to the next (no allocation per search once warm).
struct SelfCollisionScratch {
  struct Hash {
    std::vector<size_t> start, fill;
    std::vector<int> ids;
  };
  Hash vertices, edges;
  /// Each edge's box padded by half the margin, for this search's positions.
  std::vector<std::array<Vec3, 2>> edge_boxes;
  /// Each edge's entries in the edges' hash, from `edge_cells_start[k]`, one per cell of its box
  /// in for_cells order: the slot, and where in it the edges above k begin.
  std::vector<size_t> edge_cells_start, edge_cells_slot, edge_cells_above;
  /// Per worker: the query that last visited each primitive (search generation and query index).
  std::vector<std::vector<uint64_t>> stamps;
  std::vector<std::vector<int>> found;
  uint64_t generation = 0;
  std::vector<std::vector<PointTrianglePair>> point_triangle_parts;
  std::vector<std::vector<EdgeEdgePair>> edge_edge_parts;
};

/// Every vertex-triangle and edge-edge pair (sharing no vertex, and not mesh neighbours: of one
/// piece with corners within 1.5 mean edges in the pattern) closer than `margin_mm` at `x`,
/// found through a spatial hash of cell size about the mean edge, in a fixed order (the same for
/// any size of `pool`, which splits the queries; null: the calling thread only). `scratch` (may be
/// null) keeps the buffers for the next search.
SelfCollisionPairs find_self_collision_pairs(const ClothModel& cloth, const std::vector<Vec3>& x, double margin_mm,
                                             ThreadPool* pool = nullptr, SelfCollisionScratch* scratch = nullptr);

/// Pushes every candidate pair found closer than `thickness_mm` (or on the other side than it
/// was found on) apart to `thickness_mm`, moving the vertices in proportion to their inverse
/// masses (Gauss-Seidel, in the pairs' order). Returns how many pairs were in contact.
int resolve_self_collisions(const ClothModel& cloth, const SelfCollisionPairs& pairs, double thickness_mm,
                            std::vector<Vec3>& x);

}  // namespace tp::geometry::internal
