// geometry/design/validate_design.h: checks a print design before anything is built from it.
#pragma once

#include "geometry/common/error.h"
#include "geometry/design/design.h"

namespace tp::geometry {

/// Checks every layer: images present with width * height pixels, finite parameters, opacity in
/// 0..1, positive sizes, non-zero directions, strokes with points and a positive radius, transfer
/// meshes whose indices are in range. Fails naming the field, e.g.
/// "design.layers[2] 'flowers': content.radius_mm must be > 0".
[[nodiscard]] Status validate_design(const Design& design);

}  // namespace tp::geometry
