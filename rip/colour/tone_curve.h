// rip/colour/tone_curve.h: per-ink linearisation (tone) curves: requested ink amount to the amount to
// lay down so that measured tone follows the request.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

/// A monotone (non-decreasing) curve through (input, output) points, both as fractions 0..1,
/// inputs strictly increasing. An empty curve is the identity. Between points the curve is a
/// monotone cubic (Fritsch-Carlson), so it never overshoots the measured points.
struct ToneCurve {
  std::vector<std::pair<double, double>> points;
};

/// Parses "in:out in:out ..." pairs in percent (0..100), separated by spaces, commas or semicolons,
/// e.g. "0:0 25:19.5 50:42 75:70 100:100". Must start at input 0 and end at input 100.
/// Fails (kColour) with `where` (e.g. "ink 'cyan' linearisation") and the offending pair number.
[[nodiscard]] Result<ToneCurve> parse_tone_curve(std::string_view text, std::string_view where);

/// Checks a curve built in code: at least two points, inputs strictly increasing from 0 to 1,
/// outputs in 0..1 and non-decreasing. Fails (kColour) naming `where` and the point.
[[nodiscard]] Status validate_tone_curve(const ToneCurve& curve, std::string_view where);

/// The curve at `input` (0..1, clamped). Precondition: the curve passed validate_tone_curve.
double evaluate(const ToneCurve& curve, double input);

}  // namespace tp::rip
