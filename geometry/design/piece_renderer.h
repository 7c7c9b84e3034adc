// geometry/design/piece_renderer.h: the seam between geometry and the RIP: render any window
// of any piece (with its allowance) at any resolution, through the correspondence.
#pragma once

#include <cstddef>

#include "geometry/common/image.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// Renders pieces of one garment job. Implementations are immutable after construction and
/// `render` is safe to call from several threads at once.
class PieceRenderer {
 public:
  virtual ~PieceRenderer() = default;

  /// Number of pieces (same order as Pattern::pieces).
  virtual int piece_count() const = 0;

  /// Cut outline of a piece (seam line plus allowance, notches not cut in), piece-local mm, CCW.
  virtual const Polygon& cut_outline_mm(int piece) const = 0;

  /// Composites a window of piece `piece` over `out`.
  ///
  /// Pixel (i, j) covers [i, i+1) x [j, j+1) in pixel space; `pixel_to_piece_mm` maps pixel
  /// space to piece-local mm (any scale, rotation or mirror). Each pixel receives the design
  /// colour (sRGB) at its centre, filtered over its footprint, with alpha = the fraction of the
  /// pixel inside the cut outline times the design's own alpha, composited src-over. Pixels the
  /// piece does not touch are left as they are.
  /// @param[in,out] out  width_px x height_px pixels, rows `row_stride_px` pixels apart
  virtual void render(int piece, const Affine2& pixel_to_piece_mm, int width_px, int height_px,
                      Rgba8* out, std::ptrdiff_t row_stride_px) const = 0;
};

}  // namespace tp::geometry
