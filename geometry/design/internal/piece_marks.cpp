// geometry/design/internal/piece_marks.cpp: mark polylines to renderer segments.
#include "geometry/design/internal/piece_marks.h"

#include "geometry/allowance/marks.h"

namespace tp::geometry::internal {

std::vector<MarkSegment> printed_marks(const Pattern& pattern, int piece, const PieceAllowance& allowance,
                                       const Finishing& finishing) {
  const PieceMarks marks = piece_marks(pattern.pieces[static_cast<size_t>(piece)], allowance, pattern.size, finishing);
  std::vector<MarkSegment> out;
  const double half = 0.5 * marks.stroke_width_mm;
  for (const auto* set : {&marks.label, &marks.grain_arrow})
    for (const auto& line : *set) {
      if (line.size() == 1) out.push_back({line[0], line[0], half});
      for (size_t i = 0; i + 1 < line.size(); ++i) out.push_back({line[i], line[i + 1], half});
    }
  return out;
}

}  // namespace tp::geometry::internal
