// geometry/nesting/placement_json.h: the placement file of `printctl bench nest --out`, readable by
// an independent checker.
#pragma once

#include <string>

#include "geometry/nesting/strip_nester.h"

namespace tp::geometry {

/// {"strip_width": w, "length": l, "placements": [{"item": <item id>, "rotation": <degrees>,
/// "mirror": <bool>, "translation": [x, y]}, ...]}, one entry per placed copy. The transform maps
/// the item's original coordinates: mirror x -> -x first, then rotation about the origin, then
/// translation; the strip runs along x, its width along y from 0. Numbers round-trip exactly.
[[nodiscard]] std::string placement_json(const StripProblem& problem, const StripSolution& solution);

}  // namespace tp::geometry
