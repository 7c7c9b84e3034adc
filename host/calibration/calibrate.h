// host/calibration/calibrate.h: `printctl calibrate`: print a profiling chart (ArgyllCMS targen)
// on the printer through the normal job path, read it (printsim's spectrophotometer, or a real
// instrument's .ti3), build the ICC profile with colprof and write a calibration set.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "host/common/error.h"

namespace tp::host {

struct CalibrateOptions {
  std::optional<std::filesystem::path> printer_model;  ///< .tpm; the built-in model otherwise
  std::string fabric = "cotton";                       ///< fabric preset loaded in the printer
  std::filesystem::path out;                           ///< calibration set folder (created)
  std::optional<std::filesystem::path> measurements;   ///< a real instrument's .ti3: skip printing
  int patches = 840;                                   ///< profiling chart size (>= 800)
  int dpi = 150;                                       ///< chart print resolution
  double aperture_mm = 4;                              ///< simulated instrument
  double noise_de = 0.2;
  std::string quality = "m";                           ///< colprof -q: l, m, h
  /// A previous profile of this printer and fabric (targen -c): the first chart's patches are
  /// spread evenly in CIELAB rather than in device RGB, so the light colours get their share.
  std::optional<std::filesystem::path> precondition;
  /// Charts printed: each after the first is spread by the profile of the ones before it; the
  /// profile is built from all of them.
  int passes = 2;
  /// Print the drop-limit, linearisation and ink-limit charts first and print the profiling
  /// charts through their results (host/calibration/ink_calibration.h). Not with measurements.
  bool ink_charts = true;
  /// Print the light-colour chart (host/calibration/light_chart.h) after the spread charts and
  /// build the profile from it too. Not with measurements.
  bool light_chart = true;
  /// Drop limit: where an ink comes within this of its heaviest patch (host/calibration/drop_limit.h).
  double drop_limit_de00 = 1.0;
};

struct CalibrateSummary {
  int patches = 0;
  double chart_area_m2 = 0;        ///< fabric the chart used (0 with --measurements)
  double seconds = 0;
  double fit_mean_de00 = 0, fit_max_de00 = 0;  ///< profcheck of the profile against its measurements
  int ink_charts = 0;                          ///< drop-limit, linearisation and ink-limit charts printed
  int light_patches = 0;                       ///< patches of the light chart printed (0: none)
  double ink_limit_percent = 0;                ///< measured total ink limit (0: none measured)
  std::filesystem::path profile;
};

/// Runs the whole calibration. Fails naming the step (targen, the chart job, the measurement,
/// colprof) and, for a broken measurement file, the file and line.
[[nodiscard]] Result<CalibrateSummary> calibrate(const CalibrateOptions& options);

/// Checks a measurement file colprof will be given: a CTI3 table with SAMPLE_ID, RGB_R/G/B device
/// values in 0..100 and XYZ_X/Y/Z or LAB_L/A/B, at least 100 patches, numbers everywhere.
[[nodiscard]] Status check_measurements(const std::filesystem::path& ti3);

}  // namespace tp::host
