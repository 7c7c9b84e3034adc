// host/calibration/ink_limit.cpp: where an overprint ramp stops changing colour.
#include "host/calibration/ink_limit.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tp::host {

/// Added before rounding to whole steps, so an amount that is a step up to rounding counts as it.
constexpr double kStepSlack = 1e-9;

Result<double> ink_limit_percent(const std::vector<RampPoint>& ramp) {
  if (ramp.size() < 3)
    return fail(ErrorCode::kValidation,
                "ink-limit chart: " + std::to_string(ramp.size()) + " totals; needs at least 3");
  if (ramp.back().amount < 1.5)
    return fail(ErrorCode::kValidation, "ink-limit chart: the heaviest overprint is " +
                                            std::to_string(ramp.back().amount * 100) + " %; needs at least 150 %");
  const device::Lab& heaviest = ramp.back().lab;
  double total = ramp.back().amount;
  for (size_t i = 1; i < ramp.size(); ++i) {
    const double de = device::delta_e_2000(ramp[i].lab, heaviest);
    if (de > kInkLimitDe00) continue;
    const double de_before = device::delta_e_2000(ramp[i - 1].lab, heaviest);
    const double t = de_before > de ? std::clamp((de_before - kInkLimitDe00) / (de_before - de), 0.0, 1.0) : 1.0;
    total = ramp[i - 1].amount + t * (ramp[i].amount - ramp[i - 1].amount);
    break;
  }
  return std::max(100.0, std::floor(total * 100 / 5 + kStepSlack) * 5);
}

}  // namespace tp::host
