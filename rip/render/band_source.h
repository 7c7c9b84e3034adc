// rip/render/band_source.h: what the RIP rasterises: anything that can paint rows of the roll at print
// resolution (a marker of pieces, a prepared image, a test pattern).
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/common/image.h"
#include "rip/common/error.h"

namespace tp::rip {

/// Rows of the print in sRGB with straight alpha (alpha 0 = unprinted fabric), at the printer's
/// resolution. Immutable while a job runs; render_rows is called from several threads at once.
class BandSource {
 public:
  virtual ~BandSource() = default;
  virtual int width_px() const = 0;
  virtual std::int64_t height_px() const = 0;
  /// Paints rows [y0, y0 + rows) into `out` (rows `stride_px` apart), which the caller has
  /// cleared to transparent. The RIP calls it with y0 a multiple of kRenderTileRows and
  /// rows = kRenderTileRows (fewer at the end), so a source's output never depends on how a job
  /// splits the roll into bands or threads.
  virtual void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const = 0;
  /// A source that reads as it goes (a file decoded while the RIP runs) reports here what went
  /// wrong; run_rip checks it after every band and stops the job with that error.
  [[nodiscard]] virtual Status status() const { return {}; }
};

/// Rows per render call: the granularity of work shared between threads.
inline constexpr int kRenderTileRows = 16;

}  // namespace tp::rip
