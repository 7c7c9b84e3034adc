// simulator/scenario/scenario.cpp: parsing and validating printsim scenario files.
#include "simulator/scenario/scenario.h"

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

namespace tp::sim {

namespace {

constexpr FaultType kAllFaults[] = {FaultType::kStall,     FaultType::kDropFrame,  FaultType::kCorruptCrc,
                                    FaultType::kUnplug,    FaultType::kInkLow,     FaultType::kCoverOpen,
                                    FaultType::kMediaOut,  FaultType::kMediaJam,   FaultType::kHeadStrike,
                                    FaultType::kCutterNotReady, FaultType::kEmergencyStop, FaultType::kPowerLoss,
                                    FaultType::kBufferClear};

bool needs_duration(FaultType t) {
  return t == FaultType::kUnplug || t == FaultType::kPowerLoss || t == FaultType::kInkLow || t == FaultType::kCoverOpen ||
         t == FaultType::kMediaOut || t == FaultType::kCutterNotReady;
}

bool frame_fault(FaultType t) { return t == FaultType::kDropFrame || t == FaultType::kCorruptCrc; }

}  // namespace

std::string_view to_string(FaultType type) {
  switch (type) {
    case FaultType::kStall: return "stall";
    case FaultType::kDropFrame: return "drop_frame";
    case FaultType::kCorruptCrc: return "corrupt_crc";
    case FaultType::kUnplug: return "unplug";
    case FaultType::kInkLow: return "ink_low";
    case FaultType::kCoverOpen: return "cover_open";
    case FaultType::kMediaOut: return "media_out";
    case FaultType::kMediaJam: return "media_jam";
    case FaultType::kHeadStrike: return "head_strike";
    case FaultType::kCutterNotReady: return "cutter_not_ready";
    case FaultType::kEmergencyStop: return "emergency_stop";
    case FaultType::kPowerLoss: return "power_loss";
    case FaultType::kBufferClear: return "buffer_clear";
  }
  return "unknown";
}

Result<Scenario> parse_scenario(std::string_view text, std::string_view source) {
  const std::string src(source);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    return fail(ErrorCode::kScenario, src + ": not valid JSON: " + e.what());
  } catch (const nlohmann::json::exception& e) {
    // Numbers too large for a double (out_of_range.406) and the like.
    return fail(ErrorCode::kScenario, src + ": not valid JSON: " + e.what());
  }
  auto bad = [&](const std::string& pointer, const std::string& why) {
    return fail(ErrorCode::kScenario, src + ": " + pointer + ": " + why);
  };
  if (!j.is_object()) return bad("/", "expected an object");
  Scenario s;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "description") {
      if (!it->is_string()) return bad("/description", "expected a string");
      s.description = it->get<std::string>();
    } else if (it.key() == "expect" || it.key() == "job") {
      // For test runners; printsim does not look inside.
    } else if (it.key() != "faults") {
      return bad("/" + it.key(), "unknown key");
    }
  }
  if (!j.contains("faults")) return s;
  const auto& faults = j["faults"];
  if (!faults.is_array()) return bad("/faults", "expected an array");
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const std::string at = "/faults/" + std::to_string(i);
    const auto& f = faults[i];
    if (!f.is_object()) return bad(at, "expected an object");
    FaultSpec spec;
    bool typed = false;
    for (auto it = f.begin(); it != f.end(); ++it) {
      const std::string key = it.key();
      const std::string ptr = at + "/" + key;
      const auto& v = *it;
      if (key == "type") {
        if (!v.is_string()) return bad(ptr, "expected a string");
        std::string name = v.get<std::string>();
        if (name == "ink_out") name = "ink_low";  // what operators call it when it stops the printer
        for (FaultType t : kAllFaults)
          if (to_string(t) == name) {
            spec.type = t;
            typed = true;
          }
        if (!typed) return bad(ptr, "unknown fault '" + name + "'");
      } else if (key == "at_swath" || key == "at_frame" || key == "after_ms" || key == "duration_ms" || key == "count") {
        if (!v.is_number_integer() || v.get<std::int64_t>() < 0) return bad(ptr, "expected a non-negative integer");
        const auto n = v.get<std::int64_t>();
        if (key == "at_swath") {
          if (n > 0xFFFFFFFFLL) return bad(ptr, "swath index too large");
          spec.at_swath = static_cast<std::uint32_t>(n);
        } else if (key == "at_frame") {
          if (n == 0) return bad(ptr, "frames are numbered from 1");
          spec.at_frame = static_cast<std::uint64_t>(n);
        } else if (key == "after_ms") {
          spec.after_ms = n;
        } else if (key == "duration_ms") {
          if (n > 3600000) return bad(ptr, "longer than an hour");
          spec.duration_ms = n;
        } else {
          if (n < 1 || n > 1000) return bad(ptr, "must be 1..1000");
          spec.count = static_cast<std::uint32_t>(n);
        }
      } else {
        return bad(ptr, "unknown key");
      }
    }
    if (!typed) return bad(at + "/type", "missing");
    const int triggers = (spec.at_swath ? 1 : 0) + (spec.at_frame ? 1 : 0) + (spec.after_ms ? 1 : 0);
    if (triggers != 1) return bad(at, "needs exactly one of at_swath, at_frame, after_ms");
    if (frame_fault(spec.type) && !spec.at_frame) return bad(at, std::string(to_string(spec.type)) + " needs at_frame");
    if (!frame_fault(spec.type) && spec.at_frame) return bad(at + "/at_frame", "only for drop_frame and corrupt_crc");
    if (needs_duration(spec.type) && spec.duration_ms == 0) return bad(at + "/duration_ms", "missing or zero");
    s.faults.push_back(spec);
  }
  return s;
}

Result<Scenario> load_scenario(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kScenario, path.string() + ": cannot open scenario file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_scenario(text, path.string());
}

}  // namespace tp::sim
