// host/job/calibration_set.cpp: reading and checking a calibration set's manifest.
#include "host/job/calibration_set.h"

#include <fstream>
#include <nlohmann/json.hpp>

namespace tp::host {

Result<CalibrationSet> load_calibration_set(const std::filesystem::path& manifest) {
  namespace fs = std::filesystem;
  const std::string src = manifest.string();
  std::ifstream in(manifest);
  if (!in) return fail(ErrorCode::kValidation, src + ": cannot open the calibration set");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail(ErrorCode::kValidation, src + ": not a JSON object");
  if (j.value("format", "") != "tp-calibration/1")
    return fail(ErrorCode::kValidation, src + ": /format: expected \"tp-calibration/1\"");
  if (!j.contains("profile") || !j["profile"].is_string())
    return fail(ErrorCode::kValidation, src + ": /profile: the set names no profile");
  const fs::path rel = j["profile"].get<std::string>();
  if (rel.is_absolute() || rel.lexically_normal().string().starts_with(".."))
    return fail(ErrorCode::kValidation, src + ": /profile: must lie inside the set's folder");
  CalibrationSet s;
  s.manifest = manifest;
  s.profile = manifest.parent_path() / rel;
  std::error_code ec;
  if (!fs::is_regular_file(s.profile, ec))
    return fail(ErrorCode::kValidation, src + ": /profile: " + s.profile.string() + " does not exist");
  s.fabric = j.value("fabric", "");
  s.patches = j.value("patches", 0);
  return s;
}

}  // namespace tp::host
