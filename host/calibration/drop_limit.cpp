// host/calibration/drop_limit.cpp: where an ink's ramp stops changing colour.
#include "host/calibration/drop_limit.h"

#include <algorithm>
#include <string>

namespace tp::host {

namespace {
constexpr double kMinInkDe00 = 3;  ///< an ink whose solid is closer to the fabric does not print
}  // namespace

Result<double> drop_limit(const std::vector<RampPoint>& ramp, std::string_view ink, double within_de00) {
  const std::string who = "ink '" + std::string(ink) + "' drop-limit chart";
  if (ramp.size() < 3)
    return fail(ErrorCode::kValidation, who + ": " + std::to_string(ramp.size()) + " amounts; needs at least 3");
  if (ramp.front().amount > 0) return fail(ErrorCode::kValidation, who + ": no unprinted patch (amount 0)");
  if (ramp.back().amount < 0.9)
    return fail(ErrorCode::kValidation, who + ": the heaviest patch is " + std::to_string(ramp.back().amount * 100) +
                                            " % of solid; needs at least 90 %");
  if (!(within_de00 > 0 && within_de00 <= 10))
    return fail(ErrorCode::kInvalidArgument,
                who + ": drop-limit threshold " + std::to_string(within_de00) + " dE00 outside 0..10");
  const device::Lab& heaviest = ramp.back().lab;
  const double ink_de = device::delta_e_2000(ramp.front().lab, heaviest);
  if (ink_de < kMinInkDe00)
    return fail(ErrorCode::kValidation,
                who + ": solid is " + std::to_string(ink_de) + " dE00 from the bare fabric: the ink does not print");
  // The first patch within the threshold of the heaviest; the crossing interpolated from the one before.
  for (size_t i = 1; i < ramp.size(); ++i) {
    const double de = device::delta_e_2000(ramp[i].lab, heaviest);
    if (de > within_de00) continue;
    const double de_before = device::delta_e_2000(ramp[i - 1].lab, heaviest);
    const double t = de_before > de ? std::clamp((de_before - within_de00) / (de_before - de), 0.0, 1.0) : 1.0;
    return ramp[i - 1].amount + t * (ramp[i].amount - ramp[i - 1].amount);
  }
  return ramp.back().amount;
}

}  // namespace tp::host
