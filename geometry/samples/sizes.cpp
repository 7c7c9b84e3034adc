// geometry/samples/sizes.cpp: the standard sizes' measurements.
#include "geometry/samples/sizes.h"

#include <string>

namespace tp::geometry::samples {

Result<BodyMeasurements> standard_size(std::string_view size) {
  BodyMeasurements m;  // defaults are size M
  if (size == "M") return m;
  // Grading: girths step 80 mm, lengths a little, per size (common women's grade rules).
  double step = 0;
  if (size == "S") step = -1;
  else if (size == "L") step = 1;
  else return fail(ErrorCode::kInvalidArgument, "unknown size '" + std::string(size) + "' (S, M or L)");
  m.height_mm += 40 * step;
  m.bust_mm += 80 * step;
  m.underbust_mm += 70 * step;
  m.waist_mm += 80 * step;
  m.hips_mm += 80 * step;
  m.neck_mm += 15 * step;
  m.shoulder_width_mm += 12 * step;
  m.back_length_mm += 8 * step;
  m.armscye_depth_mm += 7 * step;
  m.upper_arm_mm += 25 * step;
  m.wrist_mm += 8 * step;
  m.arm_length_mm += 10 * step;
  m.waist_to_hip_mm += 5 * step;
  m.waist_to_knee_mm += 15 * step;
  m.bust_span_mm += 8 * step;
  return m;
}

Result<BodyMeasurements> parse_size(std::string_view text) {
  std::string_view size = "M", rest = text;
  size_t colon = text.find(':');
  if (colon != std::string_view::npos) {
    size = text.substr(0, colon);
    rest = text.substr(colon + 1);
  } else if (text.find('=') == std::string_view::npos) {
    size = text;
    rest = {};
  }
  auto base = standard_size(size);
  if (!base) return base;
  return parse_measurements(rest, *base);
}

}  // namespace tp::geometry::samples
