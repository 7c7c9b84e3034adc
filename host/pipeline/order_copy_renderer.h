// host/pipeline/order_copy_renderer.h: one personalised copy of an order size: the size's shared
// renderer (garment, images, every layer but the copy's text) with the copy's own text and labels
// drawn over it, so the copies of a size hold one full renderer between them.
#pragma once

#include <memory>

#include "geometry/design/piece_renderer.h"

namespace tp::host {

/// Renders `base` (shared by every copy of a size) and then `overlay` (the copy's personalised
/// text layers and printed marks, built on the same pattern and garment, so the same pieces and
/// cut outlines) over it. Exact when the overlay's layers are the design's top layers: inside the
/// cut outline each pixel is the base's colour with the text composited over it, as one renderer
/// of all layers gives; on the outline's anti-aliased edge the text's alpha is applied twice.
class OrderCopyRenderer final : public geometry::PieceRenderer {
 public:
  OrderCopyRenderer(std::shared_ptr<const geometry::PieceRenderer> base,
                    std::shared_ptr<const geometry::PieceRenderer> overlay)
      : base_(std::move(base)), overlay_(std::move(overlay)) {}
  int piece_count() const override { return base_->piece_count(); }
  const geometry::Polygon& cut_outline_mm(int piece) const override { return base_->cut_outline_mm(piece); }
  void render(int piece, const geometry::Affine2& pixel_to_piece_mm, int width_px, int height_px, geometry::Rgba8* out,
              std::ptrdiff_t row_stride_px) const override {
    base_->render(piece, pixel_to_piece_mm, width_px, height_px, out, row_stride_px);
    overlay_->render(piece, pixel_to_piece_mm, width_px, height_px, out, row_stride_px);
  }

 private:
  std::shared_ptr<const geometry::PieceRenderer> base_;
  std::shared_ptr<const geometry::PieceRenderer> overlay_;
};

}  // namespace tp::host
