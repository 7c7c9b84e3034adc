// host/daemon/printer_view.h: printd's live view of the printer (GET /api/v1/printer's "device"
// part and the `printer` events): fed by the print stage, read by HTTP threads.
#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>

#include "host/pipeline/printer_live.h"

namespace tp::host {

class PrinterView {
 public:
  /// Takes one update from the print stage. Returns the `printer` event's data when the printer's
  /// state or condition changed with it (or a cue fired), else nullopt.
  [[nodiscard]] std::optional<nlohmann::json> update(const PrinterLive& live);
  /// The live printer as JSON (null before any job printed): identity, state, faults, swath
  /// buffer, counters and the cutter lines' cue log.
  [[nodiscard]] nlohmann::json snapshot() const;

 private:
  mutable std::mutex mu_;
  std::optional<PrinterLive> last_;
  std::deque<CueRecord> cues_;  ///< newest last, at most kCueLog
  std::uint64_t faults_seen_ = 0;  ///< status reports with a condition other than none, as they changed
};

}  // namespace tp::host
