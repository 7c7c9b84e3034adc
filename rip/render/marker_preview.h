// rip/render/marker_preview.h: a low-resolution picture of a whole marker (marker.png).
#pragma once

#include "geometry/common/image.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/nesting/marker.h"
#include "rip/common/error.h"

namespace tp::rip {

/// Largest preview render_marker_preview makes, in pixels (lower the dpi for longer markers).
inline constexpr std::int64_t kMaxPreviewPixels = std::int64_t{1} << 27;

/// Renders the whole marker at `dpi` (e.g. 50) through the same path as the print (MarkerSource),
/// transparent where no piece lies. Row 0 is the start of the marker, column 0 the left selvedge.
/// Fails like MarkerSource::create, and (kInvalidArgument) when the preview would exceed
/// kMaxPreviewPixels.
[[nodiscard]] Result<geometry::ImageRgba8> render_marker_preview(const geometry::Marker& marker,
                                                                 const geometry::PieceRenderer& renderer,
                                                                 double dpi = 50);

}  // namespace tp::rip
