// host/calibration/ink_calibration.h: the charts printed ahead of the profiling chart: drop limit,
// linearisation per ink and total ink limit, each printed in device values and read back.
#pragma once

#include <filesystem>
#include <vector>

#include "host/calibration/calibrate.h"
#include "host/job/calibration_set.h"

namespace tp::host {

struct InkCalibrationResult {
  std::vector<InkCalibration> inks;  ///< in the printer's ink order
  double ink_limit_percent = 0;      ///< 0: not measured (fewer than two colour inks)
  double chart_area_m2 = 0;
  int charts = 0;
  std::filesystem::path set;  ///< `<out>/ink-set.json`: the set without a profile
};

/// Prints, on the printer the options name, through the normal job path (`printctl run`, device
/// values by `print.device_inks`): one drop-limit chart per three inks (amounts 50..100 %), then
/// one linearisation chart per ink through the drop limits (0..100 %), then an ink-limit chart
/// (equal colour inks overprinted, through the curves); reads each with the simulated
/// spectrophotometer and writes the results as a set without a profile (`ink-set.json`), which
/// the profiling charts then print through. Fails naming the chart and step.
[[nodiscard]] Result<InkCalibrationResult> calibrate_inks(const CalibrateOptions& o, const std::filesystem::path& log);

}  // namespace tp::host
