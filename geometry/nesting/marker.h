// geometry/nesting/marker.h: a marker: where each piece lies on the fabric roll.
//
// Roll frame, mm (docs/roll-frame.md): seen from the printed face with the marker's leading edge
// at the top, x runs right across the fabric width (0 at the left selvedge) and y runs down the
// roll (0 at the marker's leading edge, growing as later rows are printed). Images of the roll
// (rows = y, columns = x) therefore show the printed face as it is, and pieces, drawn y up,
// are turned over y (the face-up flip) before their placement's mirror, rotation and offset.
#pragma once

#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// Piece-local to roll transform: the face-up flip y -> -y (piece y up, roll y down), mirror
/// x -> -x (if mirrored), rotate (counter-clockwise in the roll's x, y), then translate.
struct PiecePlacement {
  int piece = 0;              ///< index into Pattern::pieces
  double rotation_deg = 0;    ///< counter-clockwise
  bool mirrored = false;
  Vec2 offset_mm;

  Affine2 piece_to_roll() const {
    const Affine2 m = Affine2::scale(mirrored ? -1 : 1, -1);
    return Affine2::translation(offset_mm).compose(Affine2::rotation_deg(rotation_deg)).compose(m);
  }
};

/// A marker: pieces placed on a strip of fixed width.
struct Marker {
  double width_mm = 0;        ///< usable fabric width
  double length_mm = 0;       ///< used roll length
  std::vector<PiecePlacement> placements;
  double utilisation = 0;     ///< piece area / (width * length), 0..1
  double roll_start_mm = 0;   ///< where the marker starts on the roll (markers follow each other)
};

}  // namespace tp::geometry
