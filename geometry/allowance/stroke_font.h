// geometry/allowance/stroke_font.h: a small single-stroke font of the project's own design for
// piece labels (capitals, digits and a few symbols), drawn as polylines.
#pragma once

#include <string_view>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// Polylines of `text` in mm: capital height `height_mm`, baseline along +x from the origin, y up.
/// Lower case is drawn as capitals; characters the font lacks are drawn as '?'.
std::vector<std::vector<Vec2>> text_strokes(std::string_view text, double height_mm);

/// Advance width of `text` at capital height `height_mm` (no trailing gap).
double text_width_mm(std::string_view text, double height_mm);

/// Whether the font has a glyph for `c` (after upper-casing).
bool font_has_glyph(char c);

}  // namespace tp::geometry
