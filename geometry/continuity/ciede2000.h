// geometry/continuity/ciede2000.h: CIE L*a*b* from sRGB and the CIEDE2000 colour difference.
#pragma once

#include "geometry/common/image.h"

namespace tp::geometry {

/// CIE L*a*b* (D65 white).
struct Lab {
  double L = 0, a = 0, b = 0;
};

/// An sRGB pixel composited over white fabric (straight alpha), converted to L*a*b* through
/// linear light and XYZ (IEC 61966-2-1 primaries, D65 reference white).
Lab srgb_over_white_to_lab(Rgba8 pixel);

/// CIEDE2000 colour difference (Sharma, Wu and Dalal's formulation, kL = kC = kH = 1).
double ciede2000(const Lab& a, const Lab& b);

}  // namespace tp::geometry
