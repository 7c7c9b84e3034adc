// host/calibration/linearisation.cpp: inverting an ink's measured tone ramp.
#include "host/calibration/linearisation.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tp::host {

namespace {

constexpr double kMinSolidDe76 = 3;  ///< a solid closer to the fabric gives no tone to linearise

double distance76(const device::Lab& a, const device::Lab& b) {
  return std::sqrt((a.l - b.l) * (a.l - b.l) + (a.a - b.a) * (a.a - b.a) + (a.b - b.b) * (a.b - b.b));
}

}  // namespace

Result<rip::ToneCurve> linearisation_curve(const std::vector<RampPoint>& ramp, double drop_limit,
                                           std::string_view ink) {
  const std::string who = "ink '" + std::string(ink) + "' linearisation chart";
  if (!(drop_limit >= 0.05 && drop_limit <= 1))
    return fail(ErrorCode::kValidation, who + ": drop limit " + std::to_string(drop_limit) + " outside 0.05..1");
  if (ramp.size() < 3)
    return fail(ErrorCode::kValidation, who + ": " + std::to_string(ramp.size()) + " amounts; needs at least 3");
  if (ramp.front().amount > 0) return fail(ErrorCode::kValidation, who + ": no unprinted patch (amount 0)");
  if (ramp.back().amount < 0.999) return fail(ErrorCode::kValidation, who + ": the ramp stops short of 100 %");
  // Distance from the fabric per request, made non-decreasing.
  std::vector<double> dist(ramp.size(), 0.0);
  for (size_t i = 1; i < ramp.size(); ++i) dist[i] = std::max(dist[i - 1], distance76(ramp[i].lab, ramp.front().lab));
  const double full = dist.back();
  if (full < kMinSolidDe76)
    return fail(ErrorCode::kValidation,
                who + ": solid is " + std::to_string(full) + " CIELAB units from the bare fabric");
  // For each requested step, the ramp amount whose distance is that share of the full distance.
  rip::ToneCurve curve;
  for (int k = 0; k <= kLinearisationSteps; ++k) {
    const double request = static_cast<double>(k) / kLinearisationSteps;
    const double target = request * full;
    double amount = ramp.back().amount;
    for (size_t i = 1; i < ramp.size(); ++i)
      if (dist[i] >= target) {
        const double span = dist[i] - dist[i - 1];
        const double t = span > 0 ? (target - dist[i - 1]) / span : 0.0;
        amount = ramp[i - 1].amount + t * (ramp[i].amount - ramp[i - 1].amount);
        break;
      }
    double out = std::clamp(amount, 0.0, 1.0) * drop_limit;
    if (k == 0) out = 0;
    if (k == kLinearisationSteps) out = drop_limit;
    if (!curve.points.empty()) out = std::max(out, curve.points.back().second);
    curve.points.emplace_back(request, out);
  }
  if (auto ok = rip::validate_tone_curve(curve, who); !ok) return fail(ErrorCode::kValidation, ok.error().message);
  return curve;
}

}  // namespace tp::host
