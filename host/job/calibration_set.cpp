// host/job/calibration_set.cpp: reading and checking a calibration set's manifest.
#include "host/job/calibration_set.h"

#include <fstream>
#include <nlohmann/json.hpp>

namespace tp::host {

namespace {

// "/inks/<k>": name, drop_limit and linearisation [[in %, out %], ...].
Result<InkCalibration> read_ink(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) return fail(ErrorCode::kValidation, where + ": expected an object");
  InkCalibration ink;
  if (!j.contains("name") || !j["name"].is_string() || j["name"].get<std::string>().empty())
    return fail(ErrorCode::kValidation, where + "/name: an ink needs a name");
  ink.name = j["name"].get<std::string>();
  if (j.contains("drop_limit")) {
    if (!j["drop_limit"].is_number() || j["drop_limit"].get<double>() < 0.05 || j["drop_limit"].get<double>() > 1)
      return fail(ErrorCode::kValidation, where + "/drop_limit: expected a number in 0.05..1");
    ink.drop_limit = j["drop_limit"].get<double>();
  }
  if (j.contains("linearisation")) {
    const auto& c = j["linearisation"];
    if (!c.is_array()) return fail(ErrorCode::kValidation, where + "/linearisation: expected [[in %, out %], ...]");
    for (size_t k = 0; k < c.size(); ++k) {
      if (!c[k].is_array() || c[k].size() != 2 || !c[k][0].is_number() || !c[k][1].is_number())
        return fail(ErrorCode::kValidation, where + "/linearisation/" + std::to_string(k) + ": expected [in %, out %]");
      ink.linearisation.points.emplace_back(c[k][0].get<double>() / 100, c[k][1].get<double>() / 100);
    }
    if (auto ok = rip::validate_tone_curve(ink.linearisation, where + "/linearisation"); !ok)
      return fail(ErrorCode::kValidation, ok.error().message);
  }
  return ink;
}

}  // namespace

Result<CalibrationSet> load_calibration_set(const std::filesystem::path& manifest) {
  namespace fs = std::filesystem;
  const std::string src = manifest.string();
  std::ifstream in(manifest);
  if (!in) return fail(ErrorCode::kValidation, src + ": cannot open the calibration set");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail(ErrorCode::kValidation, src + ": not a JSON object");
  if (j.value("format", "") != "tp-calibration/1")
    return fail(ErrorCode::kValidation, src + ": /format: expected \"tp-calibration/1\"");
  if (!j.contains("profile") || !(j["profile"].is_string() || j["profile"].is_null()))
    return fail(ErrorCode::kValidation, src + ": /profile: the set names no profile");
  CalibrationSet s;
  s.manifest = manifest;
  std::error_code ec;
  if (j["profile"].is_string()) {
    const fs::path rel = j["profile"].get<std::string>();
    if (rel.is_absolute() || rel.lexically_normal().string().starts_with(".."))
      return fail(ErrorCode::kValidation, src + ": /profile: must lie inside the set's folder");
    s.profile = manifest.parent_path() / rel;
    if (!fs::is_regular_file(s.profile, ec))
      return fail(ErrorCode::kValidation, src + ": /profile: " + s.profile.string() + " does not exist");
  }
  s.fabric = j.value("fabric", "");
  s.patches = j.value("patches", 0);
  if (j.contains("inks")) {
    if (!j["inks"].is_array()) return fail(ErrorCode::kValidation, src + ": /inks: expected an array");
    for (size_t k = 0; k < j["inks"].size(); ++k) {
      auto ink = read_ink(j["inks"][k], src + ": /inks/" + std::to_string(k));
      if (!ink) return fail(ink.error());
      s.inks.push_back(std::move(*ink));
    }
  }
  if (j.contains("ink_limit_percent") && !j["ink_limit_percent"].is_null()) {
    const auto& v = j["ink_limit_percent"];
    if (!v.is_number() || v.get<double>() < 100 || v.get<double>() > 1500)
      return fail(ErrorCode::kValidation, src + ": /ink_limit_percent: expected a number in 100..1500 (or null)");
    s.ink_limit_percent = v.get<double>();
  }
  if (s.profile.empty() && s.inks.empty() && s.ink_limit_percent == 0)
    return fail(ErrorCode::kValidation, src + ": /profile: the set names no profile, curves or ink limit");
  return s;
}

std::vector<rip::ToneCurve> linearisation_for(const CalibrationSet& set, const std::vector<std::string>& ink_names) {
  if (set.inks.empty()) return {};
  std::vector<rip::ToneCurve> curves(ink_names.size());
  for (size_t c = 0; c < ink_names.size(); ++c)
    for (const auto& ink : set.inks)
      if (ink.name == ink_names[c]) curves[c] = ink.linearisation;
  return curves;
}

}  // namespace tp::host
