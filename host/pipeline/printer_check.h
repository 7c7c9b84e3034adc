// host/pipeline/printer_check.h: is the connected printer the one a job plans its swaths for?
#pragma once

#include <string>

#include "device/model/printer_model.h"
#include "device/protocol/messages.h"
#include "host/common/error.h"
#include "host/job/printer_choice.h"

namespace tp::host {

/// Fails (kPrinter) naming what differs when the printer's handshake (`id`) does not match the
/// model the swaths are planned for: resolution, nozzles per ink, bits per pixel, inks.
[[nodiscard]] Status check_printer(const device::PrinterModel& model, const device::IdentifyMsg& id);

/// What the preflight learned about the printer before the job's other stages ran.
struct PrinterPreflight {
  bool reached = false;  ///< the printer answered its handshake (so its identity was checked)
  std::string note;      ///< why it could not be asked, when it was not reached
};

/// Asks the printer `printer` (kSim or kUsb: the caller skips kNone) who it is, briefly and
/// without GPIO or a job, and checks it against `model`, so that a job planned for another
/// printer fails before its garment, design and RIP stages rather than after them. A printer
/// that cannot be reached now is not an error here: the print stage waits for it and fails with
/// its own message; the returned note says why it was not reached.
[[nodiscard]] Result<PrinterPreflight> preflight_printer(PrinterChoice printer, const device::PrinterModel& model);

}  // namespace tp::host
