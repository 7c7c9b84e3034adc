// host/job/calibration_set.h: a calibration set as a job names it (`print.calibration`): the
// manifest `printctl calibrate` writes (docs/colour.md) and the profile beside it.
#pragma once

#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

struct CalibrationSet {
  std::filesystem::path manifest;   ///< .../calibration.json
  std::filesystem::path profile;    ///< the RGB output profile beside it
  std::string fabric;               ///< fabric preset it was made on
  int patches = 0;
};

/// Reads `manifest` (format "tp-calibration/1"). Fails with kValidation naming the file and the
/// field: not JSON, another format, no profile, profile missing or outside the set's folder.
[[nodiscard]] Result<CalibrationSet> load_calibration_set(const std::filesystem::path& manifest);

}  // namespace tp::host
