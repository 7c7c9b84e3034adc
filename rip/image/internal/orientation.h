// rip/image/internal/orientation.h: turns a decoded image upright per its EXIF orientation tag.
#pragma once

#include "geometry/common/image.h"

namespace tp::rip {

/// Returns `img` as it is meant to be displayed for EXIF orientation 1..8 (other values: as is).
geometry::ImageRgba8 apply_exif_orientation(geometry::ImageRgba8 img, int orientation);

}  // namespace tp::rip
