// host/calibration/internal/chart_print.h: printing one calibration chart as an ordinary job on the
// printer and reading it with the simulated spectrophotometer (shared by every chart kind).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "device/model/cgats.h"
#include "host/calibration/calibrate.h"

namespace tp::host::internal {

/// Runs a program, its output appended to `log`; fails naming the step and the log.
[[nodiscard]] Status run_tool(const std::string& step, const std::vector<std::string>& argv,
                              const std::filesystem::path& log);

/// The folder of the running executable (printctl and printsim sit side by side).
std::filesystem::path own_dir();

/// How a chart job prints beyond the calibration options.
struct ChartJobExtras {
  std::vector<std::string> device_inks;  ///< R, G, B drive these inks directly (print.device_inks)
  /// A calibration set (its curves and ink limit; copied into the job) the chart prints through.
  std::optional<std::filesystem::path> calibration;
};

/// Lays out `ti1` (SAMPLE_ID, RGB_R/G/B in percent), prints it as the job `job` into `printed`,
/// finds it on the fabric and writes `base`.ti2 (patch centres) and `base`.ti3 (the readings).
/// Adds the chart's fabric to `area_m2`. Fails naming the step.
[[nodiscard]] Status print_chart(const CalibrateOptions& o, const device::CgatsTable& ti1, const std::string& source,
                                 const std::filesystem::path& base, const std::filesystem::path& job,
                                 const std::filesystem::path& printed, const ChartJobExtras& extras,
                                 const std::filesystem::path& log, double& area_m2);

std::string fmt(double v, int decimals = 3);

}  // namespace tp::host::internal
