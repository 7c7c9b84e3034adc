// host/job/printer_choice.cpp: the printer choice's names and the one "must this run under
// printsim" test.
#include "host/job/printer_choice.h"

#include "host/session/sim_reexec.h"

namespace tp::host {

namespace {
constexpr PrinterChoice kChoices[] = {PrinterChoice::kSim, PrinterChoice::kUsb, PrinterChoice::kNone};
}  // namespace

std::string_view to_string(PrinterChoice choice) {
  switch (choice) {
    case PrinterChoice::kSim: return "sim";
    case PrinterChoice::kUsb: return "usb";
    case PrinterChoice::kNone: return "none";
  }
  return "unknown";
}

std::optional<PrinterChoice> parse_printer_choice(std::string_view name) {
  for (PrinterChoice c : kChoices)
    if (to_string(c) == name) return c;
  return std::nullopt;
}

std::vector<std::string> printer_choice_names() {
  std::vector<std::string> names;
  for (PrinterChoice c : kChoices) names.emplace_back(to_string(c));
  return names;
}

bool needs_printsim(PrinterChoice choice) { return choice == PrinterChoice::kSim && !under_printsim(); }

}  // namespace tp::host
