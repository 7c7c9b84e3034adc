// rip/render/image_source.h: an image printed pixel for pixel at print resolution (test prints,
// calibration charts, the Ghostscript comparison).
#pragma once

#include <cstring>

#include "geometry/common/image.h"
#include "rip/render/band_source.h"

namespace tp::rip {

/// Band source over an in-memory image: print column x, row y is image pixel (x, y). The image
/// must outlive the source.
class ImageSource final : public BandSource {
 public:
  explicit ImageSource(const geometry::ImageRgba8& image) : image_(image) {}
  int width_px() const override { return image_.width_px; }
  std::int64_t height_px() const override { return image_.height_px; }
  void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const override {
    for (int r = 0; r < rows && y0 + r < image_.height_px; ++r)
      std::memcpy(static_cast<void*>(out + r * stride_px), &image_.at(0, static_cast<int>(y0 + r)),
                  sizeof(geometry::Rgba8) * static_cast<size_t>(image_.width_px));
  }

 private:
  const geometry::ImageRgba8& image_;
};

}  // namespace tp::rip
