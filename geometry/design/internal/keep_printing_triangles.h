// geometry/design/internal/keep_printing_triangles.h: drops the render triangles of a piece that
// print nothing and lie far from anything that prints, so an overlay renderer (a copy's text and
// labels) holds only the region it covers.
#pragma once

#include <vector>

#include "geometry/design/internal/render_data.h"

namespace tp::geometry::internal {

/// Keeps the triangles of `piece` that print something (a stroke candidate, a texture entry whose
/// texel range reaches its image, or a printed mark) and every triangle within `margin_mm` of
/// one, drops the rest and rebuilds the window grid. Inside the kept region the piece renders as
/// before: the dropped triangles would only have written transparent pixels, and the margin keeps
/// the borrow-a-neighbour rule at the outline (2 pixels, 1 row) away from printing pixels for any
/// pixel smaller than margin_mm / 3. Returns the number of triangles kept.
std::size_t keep_printing_triangles(PieceData& piece, const std::vector<LayerRuntime>& layers, double margin_mm);

}  // namespace tp::geometry::internal
