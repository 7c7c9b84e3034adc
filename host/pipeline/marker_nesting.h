// host/pipeline/marker_nesting.h: what the marker stage nests and how: a job's marker fields turned
// into the nester's items and options (also used by the RIP benchmark's nested garment).
#pragma once

#include <vector>

#include "geometry/design/piece_renderer.h"
#include "geometry/nesting/nest_pieces.h"
#include "geometry/pattern/pattern.h"
#include "host/job/job.h"

namespace tp::host {

/// One item per piece of `renderer` (its cut outline, mm), named after `pattern`'s piece, laid
/// under `marker`'s rotation and mirror rules along the piece's grain line (a zero or missing
/// grain keeps the nester's default, the piece's y axis). `pattern` holds the renderer's pieces.
[[nodiscard]] std::vector<geometry::NestItem> marker_nest_items(const geometry::Pattern& pattern,
                                                                const geometry::PieceRenderer& renderer,
                                                                const MarkerSpec& marker);

/// The roll (width, gap, selvedge and end margins, defects, longest marker) and the budget: an
/// iteration budget reads no clock (time limit 0); otherwise the time limit applies. The nester's
/// threads, workers and hooks keep their defaults.
[[nodiscard]] geometry::NestOptions marker_nest_options(const MarkerSpec& marker);

}  // namespace tp::host
