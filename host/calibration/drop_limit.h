// host/calibration/drop_limit.h: an ink's drop limit from its drop-limit chart: the most ink
// worth laying, past which the fabric shows no visible change.
#pragma once

#include <string_view>
#include <vector>

#include "host/calibration/device_readings.h"

namespace tp::host {

/// Colour difference to the heaviest patch below which more ink counts as no change (default).
inline constexpr double kDropLimitDe00 = 1.0;

/// The drop limit (0..1 of solid) of one ink from its ramp (amounts as laid, unprinted fabric
/// included): the amount at which the colour comes within `within_de00` of the heaviest patch,
/// interpolated between patches. Fails (kValidation) naming the ink: fewer than three amounts, no
/// unprinted patch, the heaviest patch under 90 % of solid, or an ink whose heaviest patch is
/// within 3 dE00 of the bare fabric (it does not print).
[[nodiscard]] Result<double> drop_limit(const std::vector<RampPoint>& ramp, std::string_view ink,
                                        double within_de00 = kDropLimitDe00);

}  // namespace tp::host
