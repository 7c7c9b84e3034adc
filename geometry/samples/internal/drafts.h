// geometry/samples/internal/drafts.h: the drafting function of each sample garment.
#pragma once

#include "geometry/body/measurements.h"
#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::samples::internal {

/// Eight-gore skirt with waistband (9 pieces), knee length, CF and CB seams.
[[nodiscard]] Result<Pattern> draft_skirt8(const BodyMeasurements& m);
/// Simple waist-length top with bust, shoulder and waist darts (4 pieces).
[[nodiscard]] Result<Pattern> draft_simple_top(const BodyMeasurements& m);
/// Blouse with princess seams and set-in sleeves (9 pieces).
[[nodiscard]] Result<Pattern> draft_blouse(const BodyMeasurements& m);
/// Knee-length princess dress with short sleeves (10 pieces).
[[nodiscard]] Result<Pattern> draft_dress(const BodyMeasurements& m);

}  // namespace tp::geometry::samples::internal
