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

/// For each point: the nearest surface point of `from`, its piece and position on that piece (piece
/// mm), and the 3D point of `to` at that piece position (the piece's nearest point when the finer
/// mesh's boundary runs inside it). Both garments must be sewings of `pattern`; fails naming the
/// garment that does not match it.
[[nodiscard]] Result<std::vector<Vec3>> transfer_surface_points(const Pattern& pattern, const Garment& from,
                                                                const Garment& to, const std::vector<Vec3>& points_mm);

}  // namespace tp::geometry
