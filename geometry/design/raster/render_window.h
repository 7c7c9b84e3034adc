// geometry/design/raster/render_window.h: renders one window of one piece (the body of
// PieceRenderer::render), row by row.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/common/vec.h"
#include "geometry/design/internal/render_data.h"

namespace tp::geometry::internal {

/// Tuning of the render loop.
struct WindowOptions {
  int max_anisotropy = 8;  ///< trilinear taps along a stretched footprint's major axis
};

/// Composites the window into `out` as PieceRenderer::render documents it: per row, exact area
/// coverage of the cut outline (signed-area accumulation), design colours at pixel centres from
/// the render triangles (exact half-open scanline rule, so shared edges are never drawn twice),
/// pixels of the outline's edge whose centre no triangle covers take their neighbour's colour.
void render_window(const PieceData& piece, const std::vector<LayerRuntime>& layers, const Affine2& pixel_to_piece_mm,
                   int width_px, int height_px, Rgba8* out, std::ptrdiff_t row_stride_px, const WindowOptions& options);

}  // namespace tp::geometry::internal
