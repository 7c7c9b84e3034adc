// geometry/nesting/internal/strip_frame.h: the one home of the change between the strip engine's
// frame and the roll frame (docs/roll-frame.md, docs/nesting.md).
#pragma once

#include <cmath>

#include "geometry/common/vec.h"
#include "geometry/nesting/marker.h"
#include "geometry/nesting/strip_nester.h"

namespace tp::geometry::nesting {

// The strip engine runs along x with the width along y (ESICUP); the roll has x across and y
// along. Swapping the axes maps one frame to the other (it is its own inverse).

/// A roll point in the strip frame.
[[nodiscard]] inline Vec2 roll_to_strip(Vec2 roll_mm) { return {roll_mm.y, roll_mm.x}; }

/// A strip point in the roll frame.
[[nodiscard]] inline Vec2 strip_to_roll(Vec2 strip_mm) { return {strip_mm.y, strip_mm.x}; }

/// A piece point (y up) in the strip item's own frame: the face-up flip that
/// PiecePlacement::piece_to_roll starts with, then the axis swap.
[[nodiscard]] inline Vec2 piece_to_strip_item(Vec2 piece_mm) { return roll_to_strip({piece_mm.x, -piece_mm.y}); }

/// Angles this close to a whole number of degrees are snapped to it (grain lines drawn at 90
/// degrees come out of atan2 with rounding noise).
inline constexpr double kAngleSnapDeg = 1e-9;

/// `deg` in [0, 360), snapped to a whole degree within kAngleSnapDeg.
[[nodiscard]] inline double normalise_deg(double deg) {
  deg = std::fmod(deg, 360.0);
  if (deg < 0) deg += 360.0;
  const double r = std::round(deg);
  if (std::fabs(deg - r) < kAngleSnapDeg) deg = r;
  return deg >= 360.0 ? deg - 360.0 : deg;
}

/// Roll pose (rotation, mirror) to strip pose: the axis swap turns the rotation round, and a mirror
/// of piece x into a mirror of strip x followed by a half turn.
[[nodiscard]] inline double roll_to_strip_deg(double roll_deg, bool mirror) {
  return normalise_deg(mirror ? 180.0 - roll_deg : -roll_deg);
}

/// Strip pose to roll pose (the inverse of roll_to_strip_deg, which has the same form).
[[nodiscard]] inline double strip_to_roll_deg(double strip_deg, bool mirror) {
  return normalise_deg(mirror ? 180.0 - strip_deg : -strip_deg);
}

/// The roll placement of piece `piece` that the strip placement `p` stands for: for every piece
/// point q, piece_to_roll(q) is strip_to_roll of p's transform of piece_to_strip_item(q).
[[nodiscard]] inline PiecePlacement strip_to_roll_placement(const StripPlacement& p, int piece) {
  PiecePlacement pp;
  pp.piece = piece;
  pp.mirrored = p.mirror;
  pp.rotation_deg = strip_to_roll_deg(p.rotation_deg, p.mirror);
  pp.offset_mm = strip_to_roll(p.translation);
  return pp;
}

}  // namespace tp::geometry::nesting
