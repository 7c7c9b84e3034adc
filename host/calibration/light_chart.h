// host/calibration/light_chart.h: the light-colour profiling chart: a dense device-value grid in
// the light corner of device RGB, where the spread charts leave the profile a few patches.
#pragma once

#include "device/model/cgats.h"

namespace tp::host {

/// Lowest device value (0..1) of the light chart on each channel, and its step: 0.70..1.00 by
/// 0.05, 7 x 7 x 7 = 343 patches. Through the cotton set's curves that corner holds every colour
/// from the bare fabric to about L* 80 (grey sRGB 200): creams, pastels, skin tones. The spread
/// charts put 18 of 1680 patches above L* 90 there, 10 to 20 ink units apart, and a design's
/// cream printed 1.26 dE00 from what the profile interpolated between them (docs/colour.md).
inline constexpr double kLightChartFrom = 0.70;
inline constexpr double kLightChartStep = 0.05;

/// The chart's device values: a CTI1 table (SAMPLE_ID, RGB_R/G/B in percent, COLOR_REP RGB), the
/// grid kLightChartFrom..1 by kLightChartStep on every channel, blue fastest.
[[nodiscard]] device::CgatsTable light_chart();

}  // namespace tp::host
