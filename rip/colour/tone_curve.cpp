// rip/colour/tone_curve.cpp: tone-curve parsing, validation and monotone cubic evaluation.
#include "rip/colour/tone_curve.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

namespace {

/// Shortest curve the parser accepts, and a guard on absurd inputs.
constexpr size_t kMaxPoints = 4096;
/// Inputs closer than this are treated as equal (the curve would be vertical).
constexpr double kInputSpacingTolerance = 1e-9;

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ';'; }

Result<double> parse_number(std::string_view s, std::string_view where, size_t pair, const char* which) {
  double v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
    return fail(ErrorCode::kColour, fmt::format("{}: pair {}: {} '{}' is not a number", where, pair, which, s));
  return v;
}

}  // namespace

Result<ToneCurve> parse_tone_curve(std::string_view text, std::string_view where) {
  ToneCurve curve;
  size_t i = 0, pair = 0;
  while (i < text.size()) {
    while (i < text.size() && is_separator(text[i])) ++i;
    if (i >= text.size()) break;
    size_t j = i;
    while (j < text.size() && !is_separator(text[j])) ++j;
    std::string_view token = text.substr(i, j - i);
    i = j;
    ++pair;
    if (pair > kMaxPoints) return fail(ErrorCode::kColour, fmt::format("{}: more than {} points", where, kMaxPoints));
    size_t colon = token.find(':');
    if (colon == std::string_view::npos)
      return fail(ErrorCode::kColour, fmt::format("{}: pair {}: '{}' is not input:output", where, pair, token));
    auto in = parse_number(token.substr(0, colon), where, pair, "input");
    if (!in) return std::unexpected(in.error());
    auto out = parse_number(token.substr(colon + 1), where, pair, "output");
    if (!out) return std::unexpected(out.error());
    curve.points.emplace_back(*in / 100.0, *out / 100.0);
  }
  auto ok = validate_tone_curve(curve, where);
  if (!ok) return std::unexpected(ok.error());
  return curve;
}

Status validate_tone_curve(const ToneCurve& curve, std::string_view where) {
  const auto& p = curve.points;
  if (p.size() < 2) return fail(ErrorCode::kColour, fmt::format("{}: needs at least 2 points, has {}", where, p.size()));
  if (std::abs(p.front().first) > kInputSpacingTolerance || std::abs(p.back().first - 1.0) > kInputSpacingTolerance)
    return fail(ErrorCode::kColour, fmt::format("{}: inputs must run from 0 to 100 %, got {} to {}", where,
                                                p.front().first * 100, p.back().first * 100));
  for (size_t i = 0; i < p.size(); ++i) {
    if (!(p[i].second >= 0.0 && p[i].second <= 1.0))
      return fail(ErrorCode::kColour, fmt::format("{}: point {}: output {} % is outside 0..100", where, i + 1,
                                                  p[i].second * 100));
    if (i > 0 && !(p[i].first - p[i - 1].first > kInputSpacingTolerance))
      return fail(ErrorCode::kColour, fmt::format("{}: point {}: input {} % does not increase", where, i + 1,
                                                  p[i].first * 100));
    if (i > 0 && p[i].second < p[i - 1].second)
      return fail(ErrorCode::kColour, fmt::format("{}: point {}: output {} % decreases (curves must be monotone)",
                                                  where, i + 1, p[i].second * 100));
  }
  return {};
}

double evaluate(const ToneCurve& curve, double x) {
  const auto& p = curve.points;
  if (p.size() < 2) return std::clamp(x, 0.0, 1.0);
  x = std::clamp(x, p.front().first, p.back().first);
  size_t k = static_cast<size_t>(std::upper_bound(p.begin(), p.end(), x,
                                                  [](double v, const auto& q) { return v < q.first; }) -
                                 p.begin());
  k = std::clamp<size_t>(k, 1, p.size() - 1);
  const size_t i = k - 1;
  // Fritsch-Carlson: tangents are secant averages, zero at flat spots or extrema, then limited
  // per segment so the cubic stays monotone.
  auto secant = [&](size_t j) { return (p[j + 1].second - p[j].second) / (p[j + 1].first - p[j].first); };
  auto tangent = [&](size_t j) {
    if (j == 0) return secant(0);
    if (j == p.size() - 1) return secant(j - 1);
    const double a = secant(j - 1), b = secant(j);
    if (a <= 0 || b <= 0) return 0.0;
    return (a + b) / 2;
  };
  const double h = p[i + 1].first - p[i].first, t = (x - p[i].first) / h;
  double m0 = tangent(i), m1 = tangent(i + 1);
  const double d = secant(i);
  if (d == 0) return p[i].second;
  const double a = m0 / d, b = m1 / d, s = a * a + b * b;
  if (s > 9) {
    const double tau = 3 / std::sqrt(s);
    m0 = tau * a * d;
    m1 = tau * b * d;
  }
  const double t2 = t * t, t3 = t2 * t;
  const double y = (2 * t3 - 3 * t2 + 1) * p[i].second + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * p[i + 1].second +
                   (t3 - t2) * h * m1;
  return std::clamp(y, std::min(p[i].second, p[i + 1].second), std::max(p[i].second, p[i + 1].second));
}

}  // namespace tp::rip
