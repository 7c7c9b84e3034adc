// geometry/pattern/darts.h: finding darts drawn into a piece outline.
#pragma once

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Widest dart opening (degrees between the legs at the tip) that is still taken for a dart.
inline constexpr double kMaxDartOpening_deg = 60;
/// Dart legs may differ in length by this fraction of the longer one (drafting rounds them).
inline constexpr double kDartLegLengthTolerance = 0.03;

/// Adds a Dart for every outline vertex that is a dart tip: the outline turns back on itself
/// there (opening under kMaxDartOpening_deg, the fabric wrapping round the tip) and the edges
/// into and out of it have nearly equal length. Legs already in a dart are skipped.
/// Returns the number of darts added. Needs a counter-clockwise outline.
int detect_darts(Piece& piece);

}  // namespace tp::geometry
