// rip/render/marker_preview.cpp: whole-marker preview through the band renderer.
#include "rip/render/marker_preview.h"

#include <spdlog/fmt/fmt.h>

#include "rip/render/marker_source.h"

namespace tp::rip {

Result<geometry::ImageRgba8> render_marker_preview(const geometry::Marker& marker,
                                                   const geometry::PieceRenderer& renderer, double dpi) {
  auto src = MarkerSource::create(marker, renderer, dpi, dpi);
  if (!src) return std::unexpected(src.error());
  const MarkerSource& s = **src;
  if (static_cast<std::int64_t>(s.width_px()) * s.height_px() > kMaxPreviewPixels)
    return fail(ErrorCode::kInvalidArgument, fmt::format("marker preview: {}x{} px at {} dpi is too large",
                                                         s.width_px(), s.height_px(), dpi));
  geometry::ImageRgba8 img;
  img.width_px = s.width_px();
  img.height_px = static_cast<int>(s.height_px());
  img.pixels.resize(static_cast<size_t>(img.width_px) * img.height_px);
  img.source = "marker preview";
  for (std::int64_t y = 0; y < s.height_px(); y += kRenderTileRows) {
    const int rows = static_cast<int>(std::min<std::int64_t>(kRenderTileRows, s.height_px() - y));
    s.render_rows(y, rows, img.pixels.data() + y * img.width_px, img.width_px);
  }
  return img;
}

}  // namespace tp::rip
