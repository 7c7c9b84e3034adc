// device/protocol/status_codes.cpp: names and operator messages of printer states and conditions.
#include "device/protocol/status_codes.h"

namespace tp::device {

std::string_view to_string(PrinterState state) {
  switch (state) {
    case PrinterState::kIdle: return "idle";
    case PrinterState::kJob: return "job";
    case PrinterState::kPrinting: return "printing";
    case PrinterState::kFeeding: return "feeding";
    case PrinterState::kWaitingForCue: return "waiting_for_cue";
    case PrinterState::kPaused: return "paused";
    case PrinterState::kFault: return "fault";
    case PrinterState::kAborting: return "aborting";
  }
  return "unknown";
}

std::string_view to_string(PrinterCondition condition) {
  switch (condition) {
    case PrinterCondition::kNone: return "none";
    case PrinterCondition::kInkLow: return "ink_low";
    case PrinterCondition::kCoverOpen: return "cover_open";
    case PrinterCondition::kMediaOut: return "media_out";
    case PrinterCondition::kHostPause: return "host_pause";
    case PrinterCondition::kHeadStrike: return "head_strike";
    case PrinterCondition::kMediaJam: return "media_jam";
    case PrinterCondition::kEmergencyStop: return "emergency_stop";
    case PrinterCondition::kBufferOverrun: return "buffer_overrun";
    case PrinterCondition::kSwathCorrupt: return "swath_corrupt";
  }
  return "unknown";
}

std::string_view to_string(JobOutcome outcome) {
  switch (outcome) {
    case JobOutcome::kNone: return "none";
    case JobOutcome::kCompleted: return "completed";
    case JobOutcome::kAborted: return "aborted";
    case JobOutcome::kFailed: return "failed";
    case JobOutcome::kLost: return "lost";
  }
  return "unknown";
}

std::string_view to_string(CueKind kind) {
  switch (kind) {
    case CueKind::kCut: return "cut";
    case CueKind::kNotch: return "notch";
  }
  return "unknown";
}

std::string_view describe(PrinterCondition condition) {
  switch (condition) {
    case PrinterCondition::kNone: return "printing normally";
    case PrinterCondition::kInkLow: return "ink low: an ink reservoir is below the printable level; refill to resume";
    case PrinterCondition::kCoverOpen: return "cover open: close the printhead cover to resume";
    case PrinterCondition::kMediaOut: return "media out: load a new roll to resume";
    case PrinterCondition::kHostPause: return "paused by the host";
    case PrinterCondition::kHeadStrike: return "head strike: the printhead touched the fabric; inspect the head";
    case PrinterCondition::kMediaJam: return "media jam: clear the fabric path";
    case PrinterCondition::kEmergencyStop: return "emergency stop pressed";
    case PrinterCondition::kBufferOverrun: return "swath buffer overrun: the host sent a swath without credit";
    case PrinterCondition::kSwathCorrupt: return "swath corrupt: data did not match its CRC or size";
  }
  return "unknown condition";
}

bool is_fault(PrinterCondition condition) { return static_cast<std::uint16_t>(condition) >= 16; }

}  // namespace tp::device
