// geometry/pattern/freesewing_sizes.cpp: FreeSewing's neck-graded female sizes mapped onto BodyMeasurements.
#include "geometry/pattern/import/freesewing_sizes.h"

#include <cctype>
#include <cstdlib>
#include <string>

#include "geometry/body/dress_form.h"

namespace tp::geometry {
namespace {

// FreeSewing's base female set (mm; neck 340) and how each measurement grades with the neck.
constexpr double kBaseNeck_mm = 340;
struct Graded {
  double base_mm;
  double ratio;
};
double graded(Graded g, double neck_mm) { return g.base_mm + (neck_mm / kBaseNeck_mm - 1) * g.base_mm * g.ratio; }

constexpr Graded kChest{925, 1}, kUnderbust{780, 1}, kWaist{750, 0.85}, kSeat{1010, 0.6}, kBiceps{270, 1},
    kWrist{165, 0.5}, kShoulderToShoulder{415, 0.65}, kHpsToWaistBack{395, 0.65}, kWaistToArmhole{170, 0.65},
    kShoulderToWrist{590, 0.3}, kWaistToSeat{250, 0.65}, kWaistToKnee{600, 0.65}, kBustSpan{160, 0.5},
    kWaistToFloor{1050, 0.4};
constexpr double kShoulderSlope_deg = 13;
// The dress form's nape sits at this fraction of the height (BodyMeasurements::nape_height_mm).
constexpr double kNapeRatio = 0.859;
// Steps fitting the form's nape to hpsToWaistBack (each leaves a fraction of a mm more).
constexpr int kBackLengthSteps = 4;

}  // namespace

std::optional<int> freesewing_size_in_name(std::string_view name) {
  const std::string_view key = "cisFemaleAdult";
  size_t at = name.find(key);
  if (at == std::string_view::npos) return std::nullopt;
  std::string digits;
  for (size_t i = at + key.size(); i < name.size() && std::isdigit(static_cast<unsigned char>(name[i])); ++i)
    digits += name[i];
  if (digits.empty() || digits.size() > 3) return std::nullopt;
  return std::atoi(digits.c_str());
}

std::optional<BodyMeasurements> freesewing_cis_female_adult(int size) {
  if (size < 28 || size > 46 || size % 2) return std::nullopt;
  const double neck = size * 10.0;
  BodyMeasurements m;
  m.neck_mm = neck;
  m.bust_mm = graded(kChest, neck);
  m.underbust_mm = graded(kUnderbust, neck);
  m.waist_mm = graded(kWaist, neck);
  m.hips_mm = graded(kSeat, neck);
  m.upper_arm_mm = graded(kBiceps, neck);
  m.wrist_mm = graded(kWrist, neck);
  m.shoulder_width_mm = graded(kShoulderToShoulder, neck);
  m.arm_length_mm = graded(kShoulderToWrist, neck);
  m.waist_to_hip_mm = graded(kWaistToSeat, neck);
  m.waist_to_knee_mm = graded(kWaistToKnee, neck);
  m.bust_span_mm = graded(kBustSpan, neck);
  m.shoulder_slope_deg = kShoulderSlope_deg;
  // FreeSewing's hpsToWaistBack runs from the high point of the shoulder over the shoulder and
  // down the back; the form's back length is the nape to the waist, tens of mm shorter (bella
  // 42 hung 60 mm above the waist of a form whose nape-to-waist was hpsToWaistBack). The nape
  // is set where the form measures hpsToWaistBack; the waist stays at waistToFloor and the
  // armpit at waistToArmhole above it. Each step moves the nape by the length still missing.
  const double hps_to_waist_back = graded(kHpsToWaistBack, neck);
  const auto set_back_length = [&](double back_mm) {
    m.back_length_mm = back_mm;
    m.armscye_depth_mm = back_mm - graded(kWaistToArmhole, neck);
    m.height_mm = (graded(kWaistToFloor, neck) + back_mm) / kNapeRatio;
  };
  set_back_length(hps_to_waist_back);
  for (int step = 0; step < kBackLengthSteps; ++step)
    set_back_length(m.back_length_mm + hps_to_waist_back - dress_form_hps_to_waist_back_mm(m));
  return m;
}

}  // namespace tp::geometry
