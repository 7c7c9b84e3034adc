// geometry/allowance/cut_outline.h: the cut line of a piece: its seam line offset outwards by a
// width per edge, with corners cut as pattern makers cut them (paper Appendix A, made robust).
#pragma once

#include <vector>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/finishing.h"
#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Cut outline of a closed seam line.
///
/// The allowance of each edge is the union of one quad per polyline segment (offset along the
/// segment's outward normal by the edge's width) with mitred joins inside the edge; corners
/// between edges add the region their style asks for; the piece and all regions are united with
/// exact polygon booleans, so concave corners, tight curves and allowances wider than a narrow
/// part of the piece give a simple outline instead of the loops of a per-vertex offset.
///
/// @param[in] edges      #E polylines in mm, counter-clockwise around the piece; edge k ends where
///                       edge k+1 starts
/// @param[in] width_mm   #E allowance widths (0: cut on the seam line)
/// @param[in] corner     #E styles of the corner at the end of each edge
/// @param[in] mitre_limit  a mitre point farther than mitre_limit * width from its corner is bevelled
/// @param[in] extra      optional polygon united with the result (for example a mesh boundary)
/// @return the outer boundary, counter-clockwise, collinear points removed.
/// Fails on fewer than 3 distinct points, mismatched sizes, a clockwise outline or non-finite input.
[[nodiscard]] Result<Polygon> cut_outline(const std::vector<std::vector<Vec2>>& edges,
                                          const std::vector<double>& width_mm,
                                          const std::vector<CornerStyle>& corner, double mitre_limit,
                                          const Polygon* extra = nullptr);

/// Cut outline of a pattern piece with its resolved allowance.
[[nodiscard]] Result<Polygon> cut_outline(const Piece& piece, const PieceAllowance& allowance, double mitre_limit);

}  // namespace tp::geometry
