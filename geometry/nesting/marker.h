// geometry/nesting/marker.h: a marker: where each piece lies on the fabric roll.
//
// Roll frame, mm: x across the fabric width (0 at the left selvedge), y along the roll in the
// direction the fabric feeds (0 at the start of the marker).
#pragma once

#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// Piece-local to roll transform: mirror x -> -x (if mirrored), rotate, then translate.
struct PiecePlacement {
  int piece = 0;              ///< index into Pattern::pieces
  double rotation_deg = 0;    ///< counter-clockwise
  bool mirrored = false;
  Vec2 offset_mm;

  Affine2 piece_to_roll() const {
    Affine2 m = mirrored ? Affine2::scale(-1, 1) : Affine2{};
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
