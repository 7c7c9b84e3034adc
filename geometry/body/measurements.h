// geometry/body/measurements.h: body measurements that drive the dress form and pattern drafting.
#pragma once

#include <string>
#include <string_view>

#include "geometry/common/error.h"

namespace tp::geometry {

/// Body measurements in mm (girths all the way round, lengths along the body) and degrees.
struct BodyMeasurements {
  double height_mm = 1680;
  double bust_mm = 920;            ///< girth over the bust points
  double underbust_mm = 780;       ///< girth just under the bust
  double waist_mm = 740;           ///< girth at the natural waist
  double hips_mm = 1000;           ///< girth at the fullest hip
  double neck_mm = 360;            ///< girth at the neck base
  double shoulder_width_mm = 380;  ///< straight distance shoulder point to shoulder point
  double back_length_mm = 410;     ///< nape (neck base at the back) down to the waist
  double armscye_depth_mm = 210;   ///< nape level down to armpit level
  double upper_arm_mm = 280;       ///< girth of the upper arm
  double wrist_mm = 160;           ///< girth of the wrist
  double arm_length_mm = 590;      ///< shoulder point to wrist
  double waist_to_hip_mm = 200;    ///< waist level down to hip level
  double waist_to_knee_mm = 590;   ///< waist level down to knee level
  double bust_span_mm = 180;       ///< distance between the bust points
  double shoulder_slope_deg = 20;  ///< shoulder line below horizontal
  double arm_angle_deg = 45;       ///< dress-form arms away from vertical

  /// Height of the waist above the floor, mm (from height and back length).
  double waist_height_mm() const { return 0.859 * height_mm - back_length_mm; }
  /// Height of the nape above the floor, mm.
  double nape_height_mm() const { return 0.859 * height_mm; }
  /// Height of the bust points above the waist, mm (from the back length).
  double bust_above_waist_mm() const { return 0.44 * back_length_mm; }
};

/// Checks that every measurement is positive and plausible relative to the others; the
/// error names the field ("waist_mm 980 exceeds bust_mm 920").
[[nodiscard]] Status validate(const BodyMeasurements& m);

/// Overrides fields of `base` from "name=value,name=value" text (names as in the struct,
/// with or without the _mm/_deg suffix, e.g. "bust=940,waist=760"). Fails with kParse naming
/// the unknown field or bad number.
[[nodiscard]] Result<BodyMeasurements> parse_measurements(std::string_view text, const BodyMeasurements& base);

}  // namespace tp::geometry
