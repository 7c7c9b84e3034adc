// host/pipeline/order_renderer.h: one PieceRenderer over every piece of every size and copy of
// an order, so the marker, RIP and cut files treat the order as one job.
#pragma once

#include <memory>
#include <vector>

#include "geometry/design/piece_renderer.h"

namespace tp::host {

/// Piece k of the order is piece `piece` of `renderer` (a copy's own renderer, kept alive).
struct OrderPiece {
  std::shared_ptr<const geometry::PieceRenderer> renderer;
  int piece = 0;
};

class OrderRenderer final : public geometry::PieceRenderer {
 public:
  explicit OrderRenderer(std::vector<OrderPiece> pieces) : pieces_(std::move(pieces)) {}
  int piece_count() const override { return static_cast<int>(pieces_.size()); }
  const geometry::Polygon& cut_outline_mm(int piece) const override {
    const OrderPiece& p = pieces_[static_cast<size_t>(piece)];
    return p.renderer->cut_outline_mm(p.piece);
  }
  void render(int piece, const geometry::Affine2& pixel_to_piece_mm, int width_px, int height_px, geometry::Rgba8* out,
              std::ptrdiff_t row_stride_px) const override {
    const OrderPiece& p = pieces_[static_cast<size_t>(piece)];
    p.renderer->render(p.piece, pixel_to_piece_mm, width_px, height_px, out, row_stride_px);
  }

 private:
  std::vector<OrderPiece> pieces_;
};

}  // namespace tp::host
