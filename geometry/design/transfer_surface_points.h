// geometry/design/transfer_surface_points.h: points on one sewing of a pattern moved to the same
// places of the fabric on another sewing of it (a design made on the studio's coarse garment,
// printed on the product's finer one).
#pragma once

#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// A place on the fabric: a pattern piece and a position on it (piece mm), and how far the 3D
/// point it was found from lies off the garment's surface there.
struct PiecePoint {
  int piece = -1;  ///< index into the pattern's pieces
  Vec2 position_mm;
  Vec3 offset_mm;  ///< from the surface point to the query point
};

/// A 3D point of a garment found from a piece position, and how far outside that piece's mesh the
/// position was (0 inside; the nearest point of the piece is taken).
struct GarmentPoint {
  Vec3 position_mm;
  double outside_mm = 0;
};

/// For each 3D point, its nearest surface point on `garment` (a sewing of `pattern`) as a piece
/// position. Fails naming the garment when it does not match the pattern or has no triangles.
[[nodiscard]] Result<std::vector<PiecePoint>> locate_on_pieces(const Pattern& pattern, const Garment& garment,
                                                               const std::vector<Vec3>& points_mm);

/// For each piece position, the 3D point of `garment` there (offsets are not added). Fails naming
/// the piece when the garment has no chart for it.
[[nodiscard]] Result<std::vector<GarmentPoint>> place_on_garment(const Pattern& pattern, const Garment& garment,
                                                                 const std::vector<PiecePoint>& points);

/// For each point: the nearest surface point of `from`, its piece and position on that piece (piece
/// mm), and the 3D point of `to` at that piece position (the piece's nearest point when the finer
/// mesh's boundary runs inside it). Both garments must be sewings of `pattern`; fails naming the
/// garment that does not match it.
[[nodiscard]] Result<std::vector<Vec3>> transfer_surface_points(const Pattern& pattern, const Garment& from,
                                                                const Garment& to, const std::vector<Vec3>& points_mm);

}  // namespace tp::geometry
