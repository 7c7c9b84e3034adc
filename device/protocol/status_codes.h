// device/protocol/status_codes.h: printer states, pause reasons and faults as the printer reports
// them, with messages for operators.
#pragma once

#include <cstdint>
#include <string_view>

namespace tp::device {

/// The printer controller's state (device/firmware runs the machine; the host reads it).
enum class PrinterState : std::uint8_t {
  kIdle = 0,           ///< no job
  kJob = 1,            ///< job open, waiting for swath data
  kPrinting = 2,       ///< carriage pass in progress
  kFeeding = 3,        ///< fabric advancing
  kWaitingForCue = 4,  ///< stopped at a cutter cue or notch mark until the host fires it
  kPaused = 5,         ///< stopped for a reason in `condition` (ink, cover, media, host)
  kFault = 6,          ///< stopped by a fault in `condition`; the job must be aborted
  kAborting = 7,       ///< discarding the buffered swaths of an aborted job
};

/// Why the printer paused or faulted; kNone while printing normally.
enum class PrinterCondition : std::uint16_t {
  kNone = 0,
  // Pauses: printing resumes once the condition clears.
  kInkLow = 1,         ///< an ink reservoir is below the printable level
  kCoverOpen = 2,
  kMediaOut = 3,
  kHostPause = 4,      ///< the host asked for a pause
  // Faults: the job cannot continue.
  kHeadStrike = 16,
  kMediaJam = 17,
  kEmergencyStop = 18,
  kBufferOverrun = 19,  ///< the host sent a swath without credit
  kSwathCorrupt = 20,   ///< a swath's data did not match its CRC or size after decompression
};

/// How the last job ended. kLost: the printer lost the job before it ended (power loss, buffer
/// cleared); what it had printed and where the fabric stood survive in the status's last_* fields.
enum class JobOutcome : std::uint8_t { kNone = 0, kCompleted = 1, kAborted = 2, kFailed = 3, kLost = 4 };

/// What a cue drives on the cutting table.
enum class CueKind : std::uint8_t { kCut = 0, kNotch = 1 };

std::string_view to_string(PrinterState state);
std::string_view to_string(PrinterCondition condition);
std::string_view to_string(JobOutcome outcome);
std::string_view to_string(CueKind kind);
/// A sentence for operators ("media jam: clear the fabric path and abort the job").
std::string_view describe(PrinterCondition condition);
/// True for conditions that stop the job for good (faults), false for pauses.
bool is_fault(PrinterCondition condition);

}  // namespace tp::device
