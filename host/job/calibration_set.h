// host/job/calibration_set.h: a calibration set as a job names it (`print.calibration`): the
// manifest `printctl calibrate` writes (docs/colour.md), its profile, per-ink curves and ink limit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "host/common/error.h"
#include "rip/colour/tone_curve.h"

namespace tp::host {

/// One ink's calibration: the drop limit (the most of the ink worth laying, 0..1 of solid) and
/// the linearisation curve that ends at it (requested amount to the amount laid, fractions).
struct InkCalibration {
  std::string name;
  double drop_limit = 1;
  rip::ToneCurve linearisation;
};

struct CalibrationSet {
  std::filesystem::path manifest;   ///< .../calibration.json
  /// The RGB output profile beside it; empty while the set is being made (`"profile": null`:
  /// the charts printed after linearisation and before the profiling chart).
  std::filesystem::path profile;
  std::string fabric;               ///< fabric preset it was made on
  int patches = 0;
  std::vector<InkCalibration> inks;  ///< empty: the set carries no linearisation
  double ink_limit_percent = 0;      ///< total ink limit the set measured; 0 = none
};

/// Reads `manifest` (format "tp-calibration/1"). Fails with kValidation naming the file and the
/// field: not JSON, another format, no profile, profile missing or outside the set's folder, an
/// ink without a name, a drop limit outside 0.05..1, a curve that is not monotone from 0 to 100,
/// an ink limit outside 100..1500.
[[nodiscard]] Result<CalibrationSet> load_calibration_set(const std::filesystem::path& manifest);

/// The set's curves in the printer's ink order (`ink_names`), identity for an ink the set does not
/// name; empty when the set has no linearisation.
std::vector<rip::ToneCurve> linearisation_for(const CalibrationSet& set, const std::vector<std::string>& ink_names);

}  // namespace tp::host
