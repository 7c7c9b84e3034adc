// simulator/printsim/printer_memory.cpp: the printer's non-volatile memory as JSON.
#include "simulator/printsim/printer_memory.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

namespace tp::sim {

using nlohmann::json;

Result<device::NonVolatileState> load_printer_memory(const std::filesystem::path& path) {
  device::NonVolatileState nv;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return nv;
  std::ifstream in(path);
  json j = json::parse(in, nullptr, false);
  const std::string where = path.string() + ": ";
  if (j.is_discarded() || !j.is_object()) return fail(ErrorCode::kInvalidArgument, where + "not a printer memory file (JSON object)");
  try {
    nv.last_job_id = j.at("last_job_id").get<std::uint64_t>();
    const auto outcome = j.at("last_outcome").get<int>();
    if (outcome < 0 || outcome > static_cast<int>(device::JobOutcome::kLost))
      return fail(ErrorCode::kInvalidArgument, where + "/last_outcome " + std::to_string(outcome) + " out of range");
    nv.last_outcome = static_cast<device::JobOutcome>(outcome);
    nv.last_printed_next = j.at("last_printed_next").get<std::uint32_t>();
    nv.last_printed_fabric_um = j.at("last_printed_fabric_um").get<std::int64_t>();
    nv.last_fabric_pos_um = j.at("last_fabric_pos_um").get<std::int64_t>();
    if (j.contains("report")) {
      const json& r = j["report"];
      device::JobReportMsg m;
      m.job_id = r.at("job_id").get<std::uint64_t>();
      m.name = r.at("name").get<std::string>();
      m.outcome = nv.last_outcome;
      m.first_swath = r.at("first_swath").get<std::uint32_t>();
      m.swaths_printed = r.at("swaths_printed").get<std::uint32_t>();
      m.feed_travel_um = r.at("feed_travel_um").get<std::int64_t>();
      m.print_time_us = r.at("print_time_us").get<std::uint64_t>();
      m.cues_fired = r.at("cues_fired").get<std::uint32_t>();
      m.overruns = r.at("overruns").get<std::uint32_t>();
      m.drops_per_ink = r.at("drops_per_ink").get<std::vector<std::uint64_t>>();
      nv.last_report = m;
    }
  } catch (const json::exception& e) {
    return fail(ErrorCode::kInvalidArgument, where + e.what());
  }
  return nv;
}

Status save_printer_memory(const std::filesystem::path& path, const device::NonVolatileState& nv) {
  json j = {{"last_job_id", nv.last_job_id},
            {"last_outcome", static_cast<int>(nv.last_outcome)},
            {"last_outcome_name", std::string(device::to_string(nv.last_outcome))},
            {"last_printed_next", nv.last_printed_next},
            {"last_printed_fabric_um", nv.last_printed_fabric_um},
            {"last_fabric_pos_um", nv.last_fabric_pos_um}};
  if (nv.last_report) {
    const auto& r = *nv.last_report;
    j["report"] = {{"job_id", r.job_id},           {"name", r.name},
                   {"first_swath", r.first_swath}, {"swaths_printed", r.swaths_printed},
                   {"feed_travel_um", r.feed_travel_um}, {"print_time_us", r.print_time_us},
                   {"cues_fired", r.cues_fired},   {"overruns", r.overruns},
                   {"drops_per_ink", r.drops_per_ink}};
  }
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << j.dump(2) << "\n";
    out.flush();
    if (!out) return fail(ErrorCode::kOutput, tmp.string() + ": cannot write the printer memory");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) return fail(ErrorCode::kOutput, path.string() + ": cannot replace the printer memory: " + ec.message());
  return {};
}

}  // namespace tp::sim
