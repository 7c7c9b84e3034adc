// rip/image/orientation.cpp: EXIF orientation (mirrors and quarter turns) applied to decoded images.
#include "rip/image/internal/orientation.h"

#include <utility>

namespace tp::rip {

geometry::ImageRgba8 apply_exif_orientation(geometry::ImageRgba8 img, int orientation) {
  if (orientation < 2 || orientation > 8) return img;
  const int w = img.width_px, h = img.height_px;
  const bool swap = orientation >= 5;
  geometry::ImageRgba8 out;
  out.width_px = swap ? h : w;
  out.height_px = swap ? w : h;
  out.source = std::move(img.source);
  out.pixels.resize(img.pixels.size());
  // For each displayed pixel (x, y), the stored pixel it shows (EXIF 2.3, tag 0x0112).
  for (int y = 0; y < out.height_px; ++y) {
    for (int x = 0; x < out.width_px; ++x) {
      int sx = x, sy = y;
      switch (orientation) {
        case 2: sx = w - 1 - x; sy = y; break;
        case 3: sx = w - 1 - x; sy = h - 1 - y; break;
        case 4: sx = x; sy = h - 1 - y; break;
        case 5: sx = y; sy = x; break;
        case 6: sx = y; sy = h - 1 - x; break;
        case 7: sx = w - 1 - y; sy = h - 1 - x; break;
        case 8: sx = w - 1 - y; sy = x; break;
        default: break;
      }
      out.at(x, y) = img.at(sx, sy);
    }
  }
  return out;
}

}  // namespace tp::rip
