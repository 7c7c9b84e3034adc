// geometry/nesting/internal/constructive.h: the constructive placement: copies, largest first, each
// at its left-most bottom-most collision-free place found by sampling and coordinate descent.
#pragma once

#include <functional>
#include <vector>

#include "geometry/nesting/internal/layout.h"
#include "geometry/nesting/internal/rng.h"
#include "geometry/nesting/internal/search.h"

namespace tp::geometry::nesting {

/// Places every copy of `layout` (all absent on entry) without collision, the collision outline
/// ending at or before `x_limit`. Returns the copies that did not fit (empty when all did).
/// Stops early (returning the rest as unplaced) when `stop()` turns true.
[[nodiscard]] std::vector<int> construct_layout(Layout& layout, double x_limit, const SampleConfig& config, Rng& rng,
                                                const std::function<bool()>& stop);

/// Copies in constructive order: largest (convex hull area times diameter) first.
[[nodiscard]] std::vector<int> constructive_order(const NestContext& ctx);

}  // namespace tp::geometry::nesting
