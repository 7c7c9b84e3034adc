// geometry/design/render_piece_image.h: a whole piece rendered into an image (previews, piece
// PNGs, tests and the design benchmark).
#pragma once

#include <vector>

#include "geometry/common/image.h"
#include "geometry/common/vec.h"
#include "geometry/design/piece_renderer.h"

namespace tp::geometry {

/// A piece image and the map from its pixel space to piece mm.
struct PieceImage {
  ImageRgba8 image;
  Affine2 pixel_to_piece_mm;  ///< pixel (i, j) covers [i, i+1) x [j, j+1); row 0 is the piece's top
};

/// Renders piece `piece` (its cut outline's bounding box plus `margin_px`) at `dpi` over a
/// transparent background, the piece's y axis pointing up the image. `rows_per_call` splits the
/// work into bands as the RIP does (0: one call).
PieceImage render_piece_image(const PieceRenderer& renderer, int piece, double dpi, int margin_px = 2,
                              int rows_per_call = 0);

/// The images of `pieces` as render_piece_image makes them (one call per piece, margin 2), their
/// rows rendered in bands on `threads` threads (<= 1: on the caller's). The same pixels whatever
/// the thread count: every pixel is rendered on its own.
std::vector<PieceImage> render_piece_images(const PieceRenderer& renderer, const std::vector<int>& pieces, double dpi,
                                            int threads);

}  // namespace tp::geometry
