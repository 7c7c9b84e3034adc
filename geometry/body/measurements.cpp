// geometry/body/measurements.cpp: validation and parsing of body measurements.
#include "geometry/body/measurements.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace tp::geometry {
namespace {

struct Field {
  const char* name;
  double BodyMeasurements::*member;
};

constexpr std::array<Field, 17> kFields{{
    {"height_mm", &BodyMeasurements::height_mm},
    {"bust_mm", &BodyMeasurements::bust_mm},
    {"underbust_mm", &BodyMeasurements::underbust_mm},
    {"waist_mm", &BodyMeasurements::waist_mm},
    {"hips_mm", &BodyMeasurements::hips_mm},
    {"neck_mm", &BodyMeasurements::neck_mm},
    {"shoulder_width_mm", &BodyMeasurements::shoulder_width_mm},
    {"back_length_mm", &BodyMeasurements::back_length_mm},
    {"armscye_depth_mm", &BodyMeasurements::armscye_depth_mm},
    {"upper_arm_mm", &BodyMeasurements::upper_arm_mm},
    {"wrist_mm", &BodyMeasurements::wrist_mm},
    {"arm_length_mm", &BodyMeasurements::arm_length_mm},
    {"waist_to_hip_mm", &BodyMeasurements::waist_to_hip_mm},
    {"waist_to_knee_mm", &BodyMeasurements::waist_to_knee_mm},
    {"bust_span_mm", &BodyMeasurements::bust_span_mm},
    {"shoulder_slope_deg", &BodyMeasurements::shoulder_slope_deg},
    {"arm_angle_deg", &BodyMeasurements::arm_angle_deg},
}};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

Status validate(const BodyMeasurements& m) {
  for (const Field& f : kFields) {
    double v = m.*(f.member);
    bool angle = std::string_view(f.name).ends_with("_deg");
    if (!std::isfinite(v) || (angle ? (v < 0 || v > 60) : v <= 0))
      return fail(ErrorCode::kInvalidArgument, std::string(f.name) + " " + num(v) + " is out of range");
  }
  const auto less = [](double a, const char* an, double b, const char* bn) -> Status {
    if (a < b) return {};
    return fail(ErrorCode::kInvalidArgument, std::string(an) + " " + num(a) + " must be less than " + bn + " " + num(b));
  };
  Status s;
  if (!(s = less(m.waist_mm, "waist_mm", m.bust_mm * 1.15, "1.15 x bust_mm"))) return s;
  if (!(s = less(m.underbust_mm, "underbust_mm", m.bust_mm, "bust_mm"))) return s;
  if (!(s = less(m.waist_mm, "waist_mm", m.hips_mm * 1.1, "1.1 x hips_mm"))) return s;
  if (!(s = less(m.neck_mm, "neck_mm", m.bust_mm * 0.6, "0.6 x bust_mm"))) return s;
  if (!(s = less(m.armscye_depth_mm, "armscye_depth_mm", m.back_length_mm * 0.8, "0.8 x back_length_mm"))) return s;
  if (!(s = less(m.back_length_mm, "back_length_mm", m.height_mm * 0.4, "0.4 x height_mm"))) return s;
  if (!(s = less(m.waist_to_knee_mm, "waist_to_knee_mm", m.height_mm * 0.45, "0.45 x height_mm"))) return s;
  if (!(s = less(m.waist_to_hip_mm, "waist_to_hip_mm", m.waist_to_knee_mm * 0.6, "0.6 x waist_to_knee_mm"))) return s;
  if (!(s = less(m.bust_span_mm, "bust_span_mm", m.bust_mm * 0.35, "0.35 x bust_mm"))) return s;
  // The dress form's sections run through the bust (0.44 x back_length_mm above the waist) and
  // then the armpit: an armpit at or under the bust leaves them out of order.
  if (!(s = less(m.bust_above_waist_mm(), "the bust's height above the waist (0.44 x back_length_mm)",
                 m.back_length_mm - m.armscye_depth_mm, "the armpit's (back_length_mm - armscye_depth_mm)")))
    return s;
  if (!(s = less(m.wrist_mm, "wrist_mm", m.upper_arm_mm, "upper_arm_mm"))) return s;
  if (!(s = less(m.neck_mm / std::numbers::pi, "neck width (neck_mm / pi)", m.shoulder_width_mm * 0.6,
                 "0.6 x shoulder_width_mm")))
    return s;
  return {};
}

Result<BodyMeasurements> parse_measurements(std::string_view text, const BodyMeasurements& base) {
  BodyMeasurements m = base;
  while (!text.empty()) {
    size_t comma = text.find(',');
    std::string_view item = text.substr(0, comma);
    text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
    if (item.empty()) continue;
    size_t eq = item.find('=');
    if (eq == std::string_view::npos)
      return fail(ErrorCode::kParse, "measurement '" + std::string(item) + "' is not name=value");
    std::string name(item.substr(0, eq));
    std::string_view value = item.substr(eq + 1);
    const Field* field = nullptr;
    for (const Field& f : kFields) {
      std::string_view fn(f.name);
      if (fn == name || fn.substr(0, fn.rfind('_')) == name) field = &f;
    }
    if (!field) return fail(ErrorCode::kParse, "unknown measurement '" + name + "'");
    double v = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || ptr != value.data() + value.size())
      return fail(ErrorCode::kParse, "measurement '" + name + "': '" + std::string(value) + "' is not a number");
    m.*(field->member) = v;
  }
  if (auto s = validate(m); !s) return std::unexpected(s.error());
  return m;
}

}  // namespace tp::geometry
