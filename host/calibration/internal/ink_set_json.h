// host/calibration/internal/ink_set_json.h: a calibration set's ink fields (drop limits,
// linearisation curves, ink limit) as its manifest writes them.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "host/job/calibration_set.h"

namespace tp::host::internal {

/// Adds `inks` ([{name, drop_limit, linearisation [[in %, out %], ...]}]) and `ink_limit_percent`
/// (null when 0) to a manifest, as load_calibration_set reads them.
inline void add_ink_fields(nlohmann::json& m, const std::vector<InkCalibration>& inks, double ink_limit_percent) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& ink : inks) {
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [in, out] : ink.linearisation.points)
      curve.push_back({std::round(in * 1e5) / 1e3, std::round(out * 1e5) / 1e3});
    list.push_back(
        {{"name", ink.name}, {"drop_limit", std::round(ink.drop_limit * 1e4) / 1e4}, {"linearisation", curve}});
  }
  m["inks"] = list;
  m["ink_limit_percent"] = ink_limit_percent > 0 ? nlohmann::json(ink_limit_percent) : nlohmann::json();
}

}  // namespace tp::host::internal
