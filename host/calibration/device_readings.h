// host/calibration/device_readings.h: the readings of a device-value chart (drop-limit,
// linearisation, ink-limit: ink amounts printed as they are) and the tone ramps in them.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "device/colour/colorimetry.h"
#include "host/common/error.h"

namespace tp::host {

/// One patch: its device values as printed (RGB_R/G/B in percent; channel k's ink amount is
/// 1 - value / 100) and the colour read (CIELAB D50, absolute).
struct DeviceReading {
  std::string id;
  std::array<double, 3> rgb_pct{};
  device::Lab lab;
};

/// Reads a CTI3 measurement file of a device-value chart: SAMPLE_ID, RGB_R/G/B in 0..100 and
/// XYZ_X/Y/Z (0..200) or LAB_L/A/B. Fails (kValidation) naming the file and the patch or field:
/// another file type, a field missing, a value that is not a number or out of range, no patches.
[[nodiscard]] Result<std::vector<DeviceReading>> read_device_readings(const std::filesystem::path& ti3);

/// A point of a tone ramp: an amount (a fraction of solid, or a total of several inks) and the
/// colour it printed, patches of the same amount averaged.
struct RampPoint {
  double amount = 0;
  device::Lab lab;
};

/// The ramp of device channel `channel` (0..2): the patches where only that channel prints
/// (the others at 100 %, unprinted), with the unprinted patches as amount 0; sorted by amount.
std::vector<RampPoint> single_channel_ramp(const std::vector<DeviceReading>& readings, int channel);

}  // namespace tp::host
