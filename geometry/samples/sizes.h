// geometry/samples/sizes.h: standard dress-form sizes (S, M, L) and size/measurement text.
#pragma once

#include <string_view>

#include "geometry/body/measurements.h"
#include "geometry/common/error.h"

namespace tp::geometry::samples {

/// Measurements of standard size "S", "M" or "L" (women's, close to EU 36, 40, 44).
/// Fails with kInvalidArgument naming the size otherwise.
[[nodiscard]] Result<BodyMeasurements> standard_size(std::string_view size);

/// A size name ("M"), measurements over size M ("bust=940,waist=760"), or both
/// ("L:hips=1120"). Fails with kParse / kInvalidArgument naming the bad field.
[[nodiscard]] Result<BodyMeasurements> parse_size(std::string_view text);

}  // namespace tp::geometry::samples
