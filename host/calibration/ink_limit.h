// host/calibration/ink_limit.h: the total ink limit from the ink-limit chart: the total past which
// more ink no longer shows.
#pragma once

#include <vector>

#include "host/calibration/device_readings.h"

namespace tp::host {

/// Colour difference to the heaviest overprint below which more ink counts as no change.
inline constexpr double kInkLimitDe00 = 1.0;

/// The total ink limit in percent of one solid (rounded down to 5 %, at least 100) from an
/// overprint ramp whose amounts are the total laid (1 = one solid's worth): the total at which
/// the colour comes within kInkLimitDe00 of the heaviest patch. Fails (kValidation): fewer than
/// three totals, or the heaviest under 150 %.
[[nodiscard]] Result<double> ink_limit_percent(const std::vector<RampPoint>& ramp);

}  // namespace tp::host
