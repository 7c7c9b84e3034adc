// host/daemon/printer_view.cpp: the live printer as JSON and the change detection for its events.
#include "host/daemon/printer_view.h"

#include <string>

namespace tp::host {

using nlohmann::json;

namespace {

constexpr std::size_t kCueLog = 64;

json cue_json(const CueRecord& c) {
  return {{"id", c.id},
          {"kind", std::string(device::to_string(c.kind))},
          {"line", c.kind == device::CueKind::kCut ? "cutter_cue" : "notch_mark"},
          {"position_um", c.position_um},
          {"x_um", c.x_um},
          {"fired_at_um", c.fired_at_um}};
}

json state_json(const device::StatusMsg& s) {
  json faults = json::array();
  if (s.condition != device::PrinterCondition::kNone)
    faults.push_back({{"condition", std::string(device::to_string(s.condition))},
                      {"text", std::string(device::describe(s.condition))},
                      {"stops_job", s.state == device::PrinterState::kFault}});
  return {{"state", std::string(device::to_string(s.state))},
          {"condition", std::string(device::to_string(s.condition))},
          {"faults", faults}};
}

}  // namespace

std::optional<json> PrinterView::update(const PrinterLive& live) {
  std::lock_guard lock(mu_);
  const bool changed = !last_ || last_->status.state != live.status.state ||
                       last_->status.condition != live.status.condition;
  if (changed && live.status.condition != device::PrinterCondition::kNone) ++faults_seen_;
  last_ = live;
  last_->fired_cue.reset();
  if (live.fired_cue) {
    cues_.push_back(*live.fired_cue);
    while (cues_.size() > kCueLog) cues_.pop_front();
  }
  if (!changed && !live.fired_cue) return std::nullopt;
  json data = state_json(live.status);
  data["job_id"] = live.status.job_id;
  data["fabric_pos_um"] = live.status.fabric_pos_um;
  if (live.fired_cue) data["cue"] = cue_json(*live.fired_cue);
  return data;
}

json PrinterView::snapshot() const {
  std::lock_guard lock(mu_);
  if (!last_) return nullptr;
  const device::IdentifyMsg& id = last_->identity;
  const device::StatusMsg& s = last_->status;
  json j = state_json(s);
  j["identity"] = {{"model", id.model}, {"ieee1284_id", id.ieee1284_id}, {"firmware", id.firmware},
                   {"protocol_version", id.protocol_version}, {"dpi_x", id.dpi_x}, {"dpi_y", id.dpi_y}};
  const std::uint32_t slots = id.swath_slots, bytes = id.swath_buffer_bytes;
  const std::uint32_t used_slots = slots >= s.free_slots ? slots - s.free_slots : 0;
  const std::uint32_t used_bytes = bytes >= s.free_bytes ? bytes - s.free_bytes : 0;
  j["swath_buffer"] = {{"slots", slots}, {"slots_used", used_slots}, {"bytes", bytes}, {"bytes_used", used_bytes},
                       {"fill", bytes > 0 ? static_cast<double>(used_bytes) / bytes : 0.0}};
  j["job_id"] = s.job_id;
  j["counters"] = {{"swaths_committed", s.swath_next}, {"swaths_printed", s.printed_next},
                   {"fabric_pos_um", s.fabric_pos_um}, {"cues_registered", s.cues_registered},
                   {"rx_crc_errors", s.rx_crc_errors}, {"rx_gaps", s.rx_gaps}, {"naks", s.naks},
                   {"fault_changes", faults_seen_}};
  j["last_job"] = {{"job_id", s.last_job_id}, {"outcome", std::string(device::to_string(s.last_outcome))}};
  json cues = json::array();
  for (const CueRecord& c : cues_) cues.push_back(cue_json(c));
  j["cutter_lines"] = cues;
  return j;
}

}  // namespace tp::host
