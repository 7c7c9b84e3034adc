// geometry/allowance/marks.h: the piece label (name, size, job) and a grain arrow, placed where the
// sewn garment hides them: in a straight stretch of seam allowance wide enough to hold them.
#pragma once

#include <string>
#include <vector>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/finishing.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Mark strokes of one piece, in piece mm.
struct PieceMarks {
  std::string text;                               ///< the label as drawn ("FRONT M JOB-12")
  std::vector<std::vector<Vec2>> label;           ///< polylines of the label text
  std::vector<std::vector<Vec2>> grain_arrow;     ///< polylines of a double-headed grain arrow (may be empty)
  double stroke_width_mm = 0.4;
  bool in_allowance = true;  ///< false: no allowance was wide enough; drawn 1.5 mm inside the seam line
};

/// Places the label "<piece> <size> <job>" (shortened or scaled down to 2 mm to fit) along the
/// longest nearly straight stretch of an edge whose allowance holds the text with 1 mm margins,
/// reading along the outline with its top towards the piece; the grain arrow goes where the
/// allowance holds the longest arrow parallel to the piece's grain line.
PieceMarks piece_marks(const Piece& piece, const PieceAllowance& allowance, const std::string& size,
                       const Finishing& finishing);

}  // namespace tp::geometry
