// host/calibration/device_readings.cpp: reading a device-value chart's measurements and its ramps.
#include "host/calibration/device_readings.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "device/model/cgats.h"

namespace tp::host {

namespace {

constexpr double kSameAmount = 1e-6;     ///< patches whose amounts differ less are replicates
constexpr double kUnprintedPct = 99.95;  ///< a channel at this value or more lays no ink

}  // namespace

Result<std::vector<DeviceReading>> read_device_readings(const std::filesystem::path& ti3) {
  auto tables = device::load_cgats(ti3);
  if (!tables) return fail(ErrorCode::kValidation, tables.error().message);
  const device::CgatsTable& t = tables->front();
  const std::string src = ti3.string();
  if (t.type != "CTI3")
    return fail(ErrorCode::kValidation, src + ": a measurement file is CTI3, this one is '" + t.type + "'");
  const bool xyz = t.field("XYZ_X") >= 0;
  if (!xyz && t.field("LAB_L") < 0)
    return fail(ErrorCode::kValidation, src + ": no measured colour: needs XYZ_X/Y/Z or LAB_L/A/B fields");
  const std::vector<std::string> need =
      xyz ? std::vector<std::string>{"RGB_R", "RGB_G", "RGB_B", "XYZ_X", "XYZ_Y", "XYZ_Z"}
          : std::vector<std::string>{"RGB_R", "RGB_G", "RGB_B", "LAB_L", "LAB_A", "LAB_B"};
  std::vector<int> col;
  for (const auto& f : need) {
    col.push_back(t.field(f));
    if (col.back() < 0)
      return fail(ErrorCode::kValidation, src + ": field " + f + " missing (a device-value chart's readings)");
  }
  const int id_col = t.field("SAMPLE_ID");
  if (id_col < 0) return fail(ErrorCode::kValidation, src + ": field SAMPLE_ID missing");
  if (t.rows.empty()) return fail(ErrorCode::kValidation, src + ": no patches");
  std::vector<DeviceReading> out;
  for (const auto& row : t.rows) {
    DeviceReading r;
    r.id = row[static_cast<size_t>(id_col)];
    double v[6];
    for (size_t k = 0; k < 6; ++k) {
      const std::string& text = row[static_cast<size_t>(col[k])];
      char* end = nullptr;
      v[k] = std::strtod(text.c_str(), &end);
      const bool range_ok = k < 3 ? v[k] >= 0 && v[k] <= 100 : !xyz || (v[k] >= 0 && v[k] <= 200);
      if (end == text.c_str() || *end || !std::isfinite(v[k]) || !range_ok)
        return fail(ErrorCode::kValidation,
                    src + ": patch " + r.id + ": " + need[k] + " = '" + text + "' is not a valid value");
    }
    r.rgb_pct = {v[0], v[1], v[2]};
    r.lab = xyz ? device::xyz_to_lab({v[3] / 100, v[4] / 100, v[5] / 100}) : device::Lab{v[3], v[4], v[5]};
    out.push_back(r);
  }
  return out;
}

std::vector<RampPoint> single_channel_ramp(const std::vector<DeviceReading>& readings, int channel) {
  // Average replicates in CIELAB (they differ by the instrument's noise only).
  std::map<double, std::pair<device::Lab, int>> sums;
  for (const auto& r : readings) {
    bool others_blank = true;
    for (int k = 0; k < 3; ++k)
      if (k != channel && r.rgb_pct[static_cast<size_t>(k)] < kUnprintedPct) others_blank = false;
    if (!others_blank) continue;
    const double amount = std::max(0.0, 1 - r.rgb_pct[static_cast<size_t>(channel)] / 100);
    auto it = sums.lower_bound(amount - kSameAmount);
    if (it == sums.end() || it->first > amount + kSameAmount)
      it = sums.emplace(amount, std::pair{device::Lab{}, 0}).first;
    it->second.first.l += r.lab.l;
    it->second.first.a += r.lab.a;
    it->second.first.b += r.lab.b;
    ++it->second.second;
  }
  std::vector<RampPoint> ramp;
  for (const auto& [amount, sum] : sums)
    ramp.push_back({amount, {sum.first.l / sum.second, sum.first.a / sum.second, sum.first.b / sum.second}});
  return ramp;
}

}  // namespace tp::host
