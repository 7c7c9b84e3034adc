// host/bench/textured_piece_renderer.h: a plain PieceRenderer over convex pieces filled with a tiled
// image, for benchmarks, tests and tools that have no garment design.
#pragma once

#include <vector>

#include "geometry/common/image.h"
#include "geometry/design/piece_renderer.h"

namespace tp::rip {

/// Each piece is a convex CCW polygon (piece mm) filled with a texture repeated across the plane:
/// texture pixel (u, v) = (p - texture_origin_mm) * texture_px_per_mm, sampled bilinearly at pixel
/// centres, edges anti-aliased by the distance of the pixel centre to the outline. Not the
/// garment's design (no correspondence, no allowance mirroring): the stand-in the RIP benchmark
/// uses until a real design renderer is plugged in, and a reference in tests.
class TexturedPieceRenderer final : public geometry::PieceRenderer {
 public:
  struct Piece {
    geometry::Polygon outline_mm;        ///< convex, counter-clockwise
    geometry::ImageHandle texture;       ///< not null, non-empty
    double texture_px_per_mm = 10;
    geometry::Vec2 texture_origin_mm;
  };
  explicit TexturedPieceRenderer(std::vector<Piece> pieces) : pieces_(std::move(pieces)) {}

  int piece_count() const override { return static_cast<int>(pieces_.size()); }
  const geometry::Polygon& cut_outline_mm(int piece) const override { return pieces_[piece].outline_mm; }
  void render(int piece, const geometry::Affine2& pixel_to_piece_mm, int width_px, int height_px,
              geometry::Rgba8* out, std::ptrdiff_t row_stride_px) const override;

 private:
  std::vector<Piece> pieces_;
};

}  // namespace tp::rip
