// geometry/design/internal/garment_surface.h: the garment as one oriented 3D surface with its
// piece charts: vertex normals, point location per piece, piece boundaries and their seam partners.
#pragma once

#include <memory>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/design/internal/piece_locator.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// One segment of a piece's boundary loop, from loop[k] to loop[k+1] (piece interior on the left).
struct BoundarySegment {
  int a = 0, b = 0;             ///< local vertex indices
  int edge = -1;                ///< outline edge the segment belongs to
  int partner_piece = -1;       ///< piece sewn to this segment (-1: unsewn)
  int partner_segment = -1;     ///< segment index in the partner's loop
  bool partner_reversed = true; ///< the partner runs b -> a (the usual right-sides-together case)
};

/// A piece chart with its boundary and locator.
struct PieceChart {
  const GarmentPiece* piece = nullptr;
  std::vector<int> loop;                 ///< boundary vertices, counter-clockwise
  std::vector<BoundarySegment> segments; ///< loop.size() segments
  PieceLocator locator;
};

/// A surface point: its 3D position and unit outward normal.
struct SurfacePoint {
  Vec3 position_mm;
  Vec3 normal;
};

/// The garment surface shared by every design layer. Built once, then read-only.
class GarmentSurface {
 public:
  /// Checks the garment against the pattern (piece count, indices, seam loops) and derives
  /// normals and seam partners. Fails naming the piece and field at fault.
  [[nodiscard]] static Result<std::unique_ptr<GarmentSurface>> build(const Pattern& pattern, const Garment& garment);

  const Garment& garment() const { return garment_; }
  int piece_count() const { return static_cast<int>(charts_.size()); }
  const PieceChart& chart(int piece) const { return charts_[static_cast<size_t>(piece)]; }
  const std::vector<Vec3>& vertex_normals() const { return normals_; }
  /// Triangles of all pieces as 3D vertex indices, outward oriented (for closest point queries).
  const std::vector<std::array<int, 3>>& triangles_3d() const { return triangles_3d_; }
  /// For each entry of triangles_3d(): {piece, triangle in the piece mesh}.
  const std::vector<std::array<int, 2>>& triangle_owner() const { return owner_; }

  /// The 3D point and normal of a chart location.
  SurfacePoint at(int piece, const ChartLocation& loc) const;
  /// 2D chart position of a location.
  Vec2 chart_position(int piece, const ChartLocation& loc) const;

 private:
  Garment garment_;
  std::vector<PieceChart> charts_;
  std::vector<Vec3> normals_;
  std::vector<std::array<int, 3>> triangles_3d_;
  std::vector<std::array<int, 2>> owner_;
};

}  // namespace tp::geometry::internal
