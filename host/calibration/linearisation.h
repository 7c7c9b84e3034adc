// host/calibration/linearisation.h: an ink's linearisation curve from its linearisation chart, so
// that the printed colour moves away from the fabric in proportion to the amount asked for.
#pragma once

#include <string_view>
#include <vector>

#include "host/calibration/device_readings.h"
#include "rip/colour/tone_curve.h"

namespace tp::host {

/// Points of the curve, 0 %, 5 %, ... 100 % of the request.
inline constexpr int kLinearisationSteps = 20;

/// The curve (requested amount to the amount to lay, fractions) of one ink from `ramp`, printed
/// through a straight drop limit (request r laid r * drop_limit; ramp amounts are requests,
/// unprinted fabric included). Target: the colour's CIELAB distance from the bare fabric grows in
/// proportion to the request, from 0 to the ramp's heaviest patch; the curve ends at the drop
/// limit. The measured distances are made non-decreasing first (the instrument's noise), so the
/// curve is monotone. Fails (kValidation) naming the ink: fewer than three amounts, no unprinted
/// patch, the ramp not reaching 100 %, a solid under 3 CIELAB units from the fabric, a drop limit
/// outside 0.05..1.
[[nodiscard]] Result<rip::ToneCurve> linearisation_curve(const std::vector<RampPoint>& ramp, double drop_limit,
                                                         std::string_view ink);

}  // namespace tp::host
