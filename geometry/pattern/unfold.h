// geometry/pattern/unfold.h: a cut-on-fold half piece opened into the whole piece.
#pragma once

#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Largest distance (mm) of a fold edge's points from the straight line through its ends.
inline constexpr double kFoldStraightnessTolerance_mm = 0.5;

/// The whole piece of a half piece cut on the fold along edge `fold_edge` (a straight edge).
/// The half outline (all edges but the fold) is followed by its mirror image across the fold
/// line; the two edges meeting each end of the fold join into one edge (the neckline or hem that
/// crosses the fold). Mirrored edges are named "<name>_mirror". Notches, darts, internal lines and
/// drill holes are mirrored too (those lying on the fold are kept once); a notch at an end of the
/// fold edge becomes a notch at the joint, one inside it a drill mark (diameter 0).
/// Sets fold_line_mm and clears fold_edge.
/// Fails (kInvalidPattern) if the edge does not exist, is not straight within
/// kFoldStraightnessTolerance_mm or has zero length, or the piece has fewer than 2 other edges.
[[nodiscard]] Result<Piece> unfold_piece(const Piece& half, int fold_edge);

}  // namespace tp::geometry
