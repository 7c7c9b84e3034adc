// rip/render/marker_source.h: a marker rendered at print resolution, band by band, through the
// design's PieceRenderer.
#pragma once

#include <memory>
#include <vector>

#include "geometry/design/piece_renderer.h"
#include "geometry/nesting/marker.h"
#include "rip/common/error.h"
#include "rip/render/band_source.h"

namespace tp::rip {

/// Paints the pieces of a marker on the roll. For each render tile only the placements whose
/// bounds cross it are drawn, each through PieceRenderer::render with the pixel -> piece-mm map
/// (the placement's inverse after the pixel -> roll-mm scale), in placement order. Memory does not
/// depend on the roll length. Pixel (i, j) covers roll mm [i, i+1) x [j, j+1) * 25.4 / dpi.
class MarkerSource final : public BandSource {
 public:
  /// Prepares the placements. The marker and renderer must outlive the source.
  /// Fails (kGeometry) naming the placement: a piece index out of range, an empty or degenerate
  /// cut outline, a non-finite transform; (kInvalidArgument) on a non-positive size or dpi.
  [[nodiscard]] static Result<std::unique_ptr<MarkerSource>> create(const geometry::Marker& marker,
                                                                     const geometry::PieceRenderer& renderer,
                                                                     double dpi_x, double dpi_y);

  int width_px() const override { return width_px_; }
  std::int64_t height_px() const override { return height_px_; }
  void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const override;

  /// Placements crossing rows [y0, y0 + rows) (for tests and diagnostics).
  int placements_crossing(std::int64_t y0, int rows) const;

 private:
  struct Item {
    int piece = 0;
    geometry::Affine2 roll_to_piece;         ///< roll mm -> piece mm
    int x0 = 0, x1 = 0;                      ///< columns [x0, x1) the piece may touch
    std::int64_t y0 = 0, y1 = 0;             ///< rows [y0, y1)
  };
  MarkerSource() = default;

  const geometry::PieceRenderer* renderer_ = nullptr;
  double dpi_x_ = 0, dpi_y_ = 0;
  int width_px_ = 0;
  std::int64_t height_px_ = 0;
  std::vector<Item> items_;  ///< in placement order
  /// For each kBucketRows-row bucket of the roll, the items crossing it, in placement order.
  std::vector<std::vector<int>> buckets_;
};

}  // namespace tp::rip
