// rip/colour/lab_image.h: reading a three-channel image (CIELAB float or 8-bit sRGB) with its
// resolution, for proof checks and chart reading.
#pragma once

#include <filesystem>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

struct Image3f {
  int width_px = 0, height_px = 0;
  double px_per_mm = 0;      ///< from XResolution and its unit
  std::vector<float> px;     ///< width * height * 3, row-major; 8-bit files read as 0..1
  const float* at(int x, int y) const { return &px[(static_cast<std::size_t>(y) * width_px + x) * 3]; }
};

/// The first three channels of `path` as float. Fails (kImage) naming the file: unreadable, fewer
/// than three channels, or no resolution.
[[nodiscard]] Result<Image3f> read_image3f(const std::filesystem::path& path);

}  // namespace tp::rip
