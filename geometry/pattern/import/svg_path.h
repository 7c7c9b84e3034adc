// geometry/pattern/import/svg_path.h: SVG path data (M/L/H/V/C/S/Q/T/A/Z) and transform attribute parsing.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// One drawing segment in absolute coordinates. Arcs are kept as SVG defines them.
struct SvgSegment {
  enum class Kind { kLine, kQuadratic, kCubic, kArc } kind = Kind::kLine;
  Vec2 from, to;
  Vec2 c1, c2;                       ///< controls: quadratic uses c1, cubic c1 and c2
  double rx = 0, ry = 0;             ///< arc radii
  double x_rotation_deg = 0;         ///< arc ellipse rotation
  bool large_arc = false, sweep = false;
};

/// A connected run of segments started by a moveto; `closed` if it ended with Z.
struct SvgSubpath {
  Vec2 start;
  std::vector<SvgSegment> segments;
  bool closed = false;
};

/// Parses path data ("M 0,0 L 10,0 c 1 2 3 4 5 6 z ..."): absolute and relative commands,
/// implicit repeats (extra pairs after M are linetos), S/T reflection, compact numbers ("1-2",
/// ".5.5", "1e-3") and compact arc flags. A closing Z adds the closing line when the pen is not
/// already at the start. Fails (kParse) at the first malformed command or number, naming the byte
/// offset; path data that is empty parses to no subpaths.
[[nodiscard]] Result<std::vector<SvgSubpath>> parse_svg_path(std::string_view d);

/// Cubic Beziers approximating an SVG elliptical arc segment to within `tolerance` (same units),
/// as {c1, c2, end} triples. Degenerate arcs (zero radius) become a straight cubic; radii too
/// small for the chord are scaled up as SVG prescribes.
std::vector<std::array<Vec2, 3>> svg_arc_to_cubics(const SvgSegment& arc, double tolerance);

/// Parses a transform attribute ("translate(10 20) scale(2) rotate(30 5 5) matrix(...)",
/// skewX, skewY) into one affine map (the leftmost applies last, as SVG composes them).
/// Fails (kParse) on an unknown function or a wrong argument count.
[[nodiscard]] Result<Affine2> parse_svg_transform(std::string_view text);

}  // namespace tp::geometry
