// geometry/allowance/notches.h: notches as the cutter cuts them into the seam allowance: at the
// pattern's named positions, at the ends of stitched spans and as balance marks on long seams.
#pragma once

#include <string>
#include <vector>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/finishing.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// One notch of a piece, piece mm.
struct NotchCut {
  std::string name;                        ///< pattern notch name, "stitch_end" or "balance"
  int edge = 0;
  double position_mm = 0;                  ///< arc length from the edge start
  NotchType type = NotchType::kSlit;
  Vec2 seam_point_mm;                      ///< on the seam line
  Vec2 cut_point_mm;                       ///< where the notch opens on the cut line
  Vec2 inward;                             ///< unit direction into the piece
  double depth_mm = 0;                     ///< from the cut line inwards
  std::vector<std::vector<Vec2>> strokes;  ///< the cut: slit line, V, T or U polyline(s)
};

/// Balance notches go on stitched spans longer than this without a notch of their own.
inline constexpr double kBalanceNotchSpan_mm = 200;

/// Notches of piece `piece` cut into `cut_outline` (its cut line): the pattern's notches, both
/// ends of every stitched span that does not end at a corner (when finishing asks for them), and
/// a balance notch at the middle of long stitched spans, matched on both pieces of the stitch.
/// Depth is finishing.notch_depth_mm, at most 60 % of the edge's allowance (3 mm into the piece
/// where there is no allowance); width finishing.notch_width_mm.
std::vector<NotchCut> piece_notches(const Pattern& pattern, int piece, const PieceAllowance& allowance,
                                    const Polygon& cut_outline, const Finishing& finishing);

}  // namespace tp::geometry
