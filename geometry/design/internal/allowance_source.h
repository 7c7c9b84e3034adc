// geometry/design/internal/allowance_source.h: where the print of a seam-allowance point comes
// from (paper section 3.6.1): across a sewn seam the strip just inside the partner piece
// (category 1), at a hem or open edge the mirror of the piece's own inner strip (category 2).
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/design/internal/garment_surface.h"

namespace tp::geometry::internal {

/// A point outside a piece's seam line in seam coordinates: boundary segment, position t along it
/// (0..1, extrapolated slightly at convex corners), and distance d outside (along mitred normals).
struct SeamCoordinates {
  int segment = -1;
  double t = 0;
  double d_mm = 0;
};

/// The source of an allowance point's print.
struct AllowanceSample {
  int piece = -1;            ///< piece whose inner strip is copied
  ChartLocation location;    ///< where in that piece's chart
  Vec2 position_mm;          ///< the copied point in that piece's frame
  int category = 2;          ///< 1: partner across a seam, 2: own strip mirrored
};

/// Seam coordinates and sources for every piece of a garment. Read-only after construction.
class AllowanceSource {
 public:
  explicit AllowanceSource(const GarmentSurface& surface);

  /// Seam coordinates of `p` (piece mm, outside or on the seam line) relative to `piece`'s boundary.
  SeamCoordinates seam_coordinates(int piece, Vec2 p) const;

  /// Seam coordinates of `p` within one boundary segment's mitred quad, t extrapolated past
  /// 0..1 when p lies beyond the quad's mitre lines (for a triangle straddling them).
  SeamCoordinates seam_coordinates_in(int piece, int segment, Vec2 p) const;

  /// The point at seam coordinates `c` of `piece`, offset by c.d_mm outwards (negative: inwards).
  Vec2 seam_point(int piece, const SeamCoordinates& c) const;

  /// Source of the allowance print at `p` in `piece`'s frame.
  AllowanceSample source(int piece, Vec2 p) const;

  /// Source for given seam coordinates (used by the continuity measurement).
  AllowanceSample source(int piece, const SeamCoordinates& c) const;

  /// Lines from the boundary vertices where the print source changes (another partner, a seam
  /// meeting an open edge) or the outline turns sharply, along their mitres, `length_mm` long:
  /// the band triangulation must not cross them.
  std::vector<std::array<Vec2, 2>> source_breaks(int piece, double length_mm) const;

 private:
  const GarmentSurface& surface_;
  // Per piece, per loop vertex: the outward mitre vector (unit perpendicular distance).
  std::vector<std::vector<Vec2>> mitre_;
};

}  // namespace tp::geometry::internal
