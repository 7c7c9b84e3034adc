// host/pipeline/order_stroke_mapping.h: a brush stroke carried from the base size's garment to
// another size's through the pieces it lies on: each point's place in its pattern piece, graded
// to the same piece of the other size, then lifted onto that size's garment.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::host {

/// A sewn size: its pattern and the 3D garment whose charts are that pattern's pieces.
struct SizedGarment {
  const geometry::Pattern* pattern = nullptr;
  const geometry::Garment* garment = nullptr;
};

/// Where a stroke point went: the piece it lies on in both sizes and the mapped 3D point.
struct MappedStrokePoint {
  std::string piece;
  geometry::Vec3 point_mm;
};

/// Maps each point: the closest point of the base garment gives (piece, position in the piece's
/// pattern mm); that position is graded to the target's piece of the same name by its place
/// relative to the seam line (mean value coordinates over the outline, each edge resampled at the
/// same fractions of its length, so a point on a seam stays at the same fraction of that seam);
/// the target garment's chart then gives the 3D point. Points keep their offset from the surface
/// along the base normal. A stroke that crosses a seam in the base size thus crosses the same
/// seam in every size, and grows or shrinks with the pieces.
///
/// Fails (nullopt, `why` set naming the piece) when a piece of the base has no namesake in the
/// target or a graded position falls outside the target piece's mesh.
[[nodiscard]] std::optional<std::vector<MappedStrokePoint>> map_stroke_through_pieces(
    const std::vector<geometry::Vec3>& points_mm, const SizedGarment& base, const SizedGarment& target,
    std::string& why);

}  // namespace tp::host
