// rip/render/marker_source.cpp: placement culling and pixel -> piece maps for rendering a marker.
#include "rip/render/marker_source.h"
#include "geometry/common/tolerances.h"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

namespace {
constexpr double kMmPerInch = 25.4;
/// Rows per culling bucket: big enough that a piece sits in few buckets, small enough that a
/// render tile sees few pieces that do not cross it.
constexpr int kBucketRows = 256;
/// Extra pixels around a piece's bounds for its anti-aliased edge and filter footprint.
constexpr int kEdgeMarginPx = 1;
/// Largest roll the RIP accepts, in rows (about 4 km at 600 dpi).
constexpr std::int64_t kMaxHeightRows = std::int64_t{1} << 26;
}  // namespace

Result<std::unique_ptr<MarkerSource>> MarkerSource::create(const geometry::Marker& marker,
                                                           const geometry::PieceRenderer& renderer, double dpi_x,
                                                           double dpi_y) {
  if (!(dpi_x > 0 && dpi_y > 0 && std::isfinite(dpi_x) && std::isfinite(dpi_y)))
    return fail(ErrorCode::kInvalidArgument, fmt::format("marker: resolution {}x{} dpi", dpi_x, dpi_y));
  if (!(marker.width_mm > 0 && marker.length_mm > 0 && std::isfinite(marker.width_mm) &&
        std::isfinite(marker.length_mm)))
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("marker: size {} x {} mm must be positive", marker.width_mm, marker.length_mm));
  const double w = std::ceil(marker.width_mm * dpi_x / kMmPerInch), h = std::ceil(marker.length_mm * dpi_y / kMmPerInch);
  if (w > (1 << 20) || h > static_cast<double>(kMaxHeightRows))
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("marker: {} x {} mm is too large at {}x{} dpi", marker.width_mm, marker.length_mm, dpi_x, dpi_y));

  std::unique_ptr<MarkerSource> src(new MarkerSource());
  src->renderer_ = &renderer;
  src->dpi_x_ = dpi_x;
  src->dpi_y_ = dpi_y;
  src->width_px_ = static_cast<int>(w);
  src->height_px_ = static_cast<std::int64_t>(h);

  for (size_t i = 0; i < marker.placements.size(); ++i) {
    const geometry::PiecePlacement& pl = marker.placements[i];
    const std::string where = fmt::format("marker placement {} (piece {})", i, pl.piece);
    if (pl.piece < 0 || pl.piece >= renderer.piece_count())
      return fail(ErrorCode::kGeometry, fmt::format("{}: piece index out of range 0..{}", where, renderer.piece_count() - 1));
    const geometry::Polygon& outline = renderer.cut_outline_mm(pl.piece);
    if (outline.size() < 3) return fail(ErrorCode::kGeometry, where + ": cut outline has fewer than 3 vertices");
    const geometry::Affine2 to_roll = pl.piece_to_roll();
    if (!std::isfinite(to_roll.a + to_roll.b + to_roll.c + to_roll.d + to_roll.e + to_roll.f) ||
        std::abs(to_roll.determinant()) < geometry::kParallelDeterminant)
      return fail(ErrorCode::kGeometry, where + ": placement transform is not finite and invertible");
    geometry::Box2 box;
    for (geometry::Vec2 p : outline) box.add(to_roll.apply(p));
    if (!std::isfinite(box.min.x + box.min.y + box.max.x + box.max.y) || box.empty())
      return fail(ErrorCode::kGeometry, where + ": cut outline is not finite");
    Item it;
    it.piece = pl.piece;
    it.roll_to_piece = to_roll.inverse();
    const double x0 = std::floor(box.min.x * dpi_x / kMmPerInch) - kEdgeMarginPx;
    const double x1 = std::ceil(box.max.x * dpi_x / kMmPerInch) + kEdgeMarginPx;
    const double y0 = std::floor(box.min.y * dpi_y / kMmPerInch) - kEdgeMarginPx;
    const double y1 = std::ceil(box.max.y * dpi_y / kMmPerInch) + kEdgeMarginPx;
    it.x0 = static_cast<int>(std::clamp(x0, 0.0, w));
    it.x1 = static_cast<int>(std::clamp(x1, 0.0, w));
    it.y0 = static_cast<std::int64_t>(std::clamp(y0, 0.0, h));
    it.y1 = static_cast<std::int64_t>(std::clamp(y1, 0.0, h));
    src->items_.push_back(it);
  }

  src->buckets_.resize(static_cast<size_t>((src->height_px_ + kBucketRows - 1) / kBucketRows));
  for (size_t i = 0; i < src->items_.size(); ++i) {
    const Item& it = src->items_[i];
    if (it.x0 >= it.x1 || it.y0 >= it.y1) continue;  // entirely off the roll
    for (std::int64_t b = it.y0 / kBucketRows; b <= (it.y1 - 1) / kBucketRows; ++b)
      src->buckets_[static_cast<size_t>(b)].push_back(static_cast<int>(i));
  }
  return src;
}

void MarkerSource::render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const {
  const std::int64_t y1 = y0 + rows;
  if (rows <= 0 || y0 < 0 || y0 >= height_px_) return;
  const double mm_per_px_x = kMmPerInch / dpi_x_, mm_per_px_y = kMmPerInch / dpi_y_;
  // Items of every bucket the rows touch, deduplicated, kept in placement order.
  std::int64_t b0 = y0 / kBucketRows, b1 = std::min<std::int64_t>((y1 - 1) / kBucketRows,
                                                                  static_cast<std::int64_t>(buckets_.size()) - 1);
  auto visit = [&](int index) {
    const Item& it = items_[static_cast<size_t>(index)];
    const std::int64_t wy0 = std::max(y0, it.y0), wy1 = std::min(y1, it.y1);
    if (wy0 >= wy1) return;
    // Window pixel (i, j) -> roll mm ((x0 + i) * mm_per_px, (wy0 + j) * mm_per_px) -> piece mm.
    const geometry::Affine2 px_to_roll{mm_per_px_x, 0, it.x0 * mm_per_px_x, 0, mm_per_px_y,
                                       static_cast<double>(wy0) * mm_per_px_y};
    renderer_->render(it.piece, it.roll_to_piece.compose(px_to_roll), it.x1 - it.x0, static_cast<int>(wy1 - wy0),
                      out + (wy0 - y0) * stride_px + it.x0, stride_px);
  };
  if (b0 == b1) {
    for (int index : buckets_[static_cast<size_t>(b0)]) visit(index);
    return;
  }
  std::vector<int> merged;
  for (std::int64_t b = b0; b <= b1; ++b)
    merged.insert(merged.end(), buckets_[static_cast<size_t>(b)].begin(), buckets_[static_cast<size_t>(b)].end());
  std::sort(merged.begin(), merged.end());
  merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
  for (int index : merged) visit(index);
}

int MarkerSource::placements_crossing(std::int64_t y0, int rows) const {
  int n = 0;
  for (const Item& it : items_)
    if (it.x0 < it.x1 && it.y0 < y0 + rows && it.y1 > y0) ++n;
  return n;
}

}  // namespace tp::rip
