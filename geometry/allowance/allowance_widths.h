// geometry/allowance/allowance_widths.h: per-edge allowance widths and corner styles of a piece,
// resolved from the job's finishing settings and the pattern's stitches.
#pragma once

#include <vector>

#include "geometry/allowance/finishing.h"
#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Resolved finishing of one piece, indexed by outline edge.
struct PieceAllowance {
  std::vector<double> width_mm;      ///< allowance width of each edge (0 on a fold)
  std::vector<bool> sewn;            ///< some stitch span lies on the edge
  std::vector<bool> hem;             ///< the edge is a hem
  std::vector<CornerStyle> corner;   ///< style of the corner at the END of each edge
};

/// Checks the finishing settings against the pattern: non-negative finite widths, overrides
/// naming existing pieces and edges. Fails naming the field ("finishing.edge_widths[2].edge").
[[nodiscard]] Status validate_finishing(const Pattern& pattern, const Finishing& finishing);

/// Widths and corner styles of piece `piece`: overrides first, then hem / sewn / other defaults;
/// a fold edge gets no allowance. Corner styles: overrides, else a reflected corner on the hem's
/// side where a hem meets another edge (if enabled), else `seam_corner`.
[[nodiscard]] Result<PieceAllowance> resolve_allowance(const Pattern& pattern, int piece, const Finishing& finishing);

}  // namespace tp::geometry
