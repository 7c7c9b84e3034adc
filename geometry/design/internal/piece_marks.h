// geometry/design/internal/piece_marks.h: a piece's printed marks as the renderer's segments.
#pragma once

#include <vector>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/finishing.h"
#include "geometry/design/internal/render_data.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// Label and grain arrow of piece `piece` (geometry/allowance/marks.h) as capsule segments.
std::vector<MarkSegment> printed_marks(const Pattern& pattern, int piece, const PieceAllowance& allowance,
                                       const Finishing& finishing);

}  // namespace tp::geometry::internal
