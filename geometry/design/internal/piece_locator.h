// geometry/design/internal/piece_locator.h: point location in one piece's 2D triangulation.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/mesh/piece_mesh.h"

namespace tp::geometry::internal {

/// A point of a piece chart: triangle index and barycentric weights of its three corners.
struct ChartLocation {
  int triangle = -1;
  std::array<double, 3> bary{};
};

/// Uniform grid over a piece's triangles for point queries in piece mm.
class PieceLocator {
 public:
  PieceLocator() = default;
  explicit PieceLocator(const PieceMesh& mesh);

  /// The triangle holding `p` (within a tiny tolerance), or triangle -1 when `p` is outside.
  ChartLocation locate(Vec2 p) const;

  /// The point of the piece nearest to `p` (p itself when inside), as a chart location.
  ChartLocation nearest(Vec2 p) const;

 private:
  const PieceMesh* mesh_ = nullptr;
  Box2 box_;
  double cell_mm_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_start_;   // CSR offsets, nx*ny + 1
  std::vector<int> cell_tris_;

  int cell_x(double x) const;
  int cell_y(double y) const;
};

/// Barycentric weights of `p` in triangle (a, b, c); all three sum to 1.
std::array<double, 3> barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c);

/// Closest point of triangle (a, b, c) to `p`, as barycentric weights.
std::array<double, 3> closest_barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c);

}  // namespace tp::geometry::internal
