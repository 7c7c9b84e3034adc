// host/job/printer_choice.h: which printer a job prints on: the simulated one, a real one over USB,
// or none (everything but printing), as one type instead of strings compared across the host.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tp::host {

enum class PrinterChoice {
  kSim,   ///< printsim's printer: the process must run under printsim (sim_reexec.h)
  kUsb,   ///< a real printer on USB; the same USB and GPIO drivers as the simulator
  kNone,  ///< no printer: the RIP runs in full, its swaths are counted and dropped
};

/// "sim", "usb", "none".
std::string_view to_string(PrinterChoice choice);
/// The choice named `name` ("sim", "usb", "none"), nullopt for anything else.
std::optional<PrinterChoice> parse_printer_choice(std::string_view name);
/// Every choice's name, for command-line checks: {"sim", "usb", "none"}.
std::vector<std::string> printer_choice_names();

/// The printer a run uses: the override when given, else the job's own.
inline PrinterChoice effective_printer(PrinterChoice job_printer, std::optional<PrinterChoice> override_printer) {
  return override_printer.value_or(job_printer);
}

/// True when `choice` is the simulated printer and this process does not run under printsim yet,
/// so it must be started again under it (printctl does; the pipeline and session refuse).
bool needs_printsim(PrinterChoice choice);

}  // namespace tp::host
