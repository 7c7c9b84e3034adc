// geometry/garment/flat_garment.h: the correspondence of a job printed flat (no body): each piece
// lies in the z = 0 plane, the pieces side by side, nothing sewn.
#pragma once

#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Space between neighbouring pieces in the flat layout, mm.
inline constexpr double kFlatLayoutGap_mm = 50;

/// Lays the meshed pieces flat: piece i's own frame is shifted along x so the pieces sit side by
/// side in pattern order, `kFlatLayoutGap_mm` apart, with their lowest point on y = 0 and z = 0.
/// A design for a flat job is made in this plane (planar projections looking along -z).
/// Fails (kInvalidArgument) when the meshes do not match the pattern's pieces.
[[nodiscard]] Result<Garment> flat_garment(const Pattern& pattern, const PatternMesh& meshes);

}  // namespace tp::geometry
