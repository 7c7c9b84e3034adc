// host/pipeline/printer_live.h: what the print stage passes on of the live printer while a job
// prints: its identity, each status report as it arrives, and each cutter cue as it fires.
#pragma once

#include <optional>

#include "device/protocol/messages.h"
#include "host/session/print_session.h"

namespace tp::host {

struct PrinterLive {
  device::IdentifyMsg identity;  ///< what the printer said it is at the handshake
  device::StatusMsg status;      ///< its latest status report
  /// Set when this update is a cue that just fired (GPIO cutter or notch line); unset for a status.
  std::optional<CueRecord> fired_cue;
};

}  // namespace tp::host
