// geometry/common/image.h: plain in-memory RGBA images handed to geometry by the layer that reads files.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tp::geometry {

/// One sRGB-encoded pixel with straight (not premultiplied) alpha.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  friend bool operator==(Rgba8, Rgba8) = default;
};

/// A decoded image in the working colour space (sRGB). Row 0 is the top row.
struct ImageRgba8 {
  int width_px = 0;
  int height_px = 0;
  std::vector<Rgba8> pixels;  ///< width_px * height_px, row-major
  std::string source;         ///< file it came from, for error messages

  Rgba8& at(int x, int y) { return pixels[static_cast<size_t>(y) * width_px + x]; }
  const Rgba8& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width_px + x]; }
};

using ImageHandle = std::shared_ptr<const ImageRgba8>;

}  // namespace tp::geometry
