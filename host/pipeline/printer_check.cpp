// host/pipeline/printer_check.cpp: the printer's handshake against the job's printer model.
#include "host/pipeline/printer_check.h"

#include <chrono>
#include <memory>

#include "host/session/print_session.h"

namespace tp::host {

Status check_printer(const device::PrinterModel& model, const device::IdentifyMsg& id) {
  auto mismatch = [&](const std::string& what, const std::string& printer, const std::string& job) {
    return fail(ErrorCode::kPrinter, "printer '" + id.model + "' " + what + " " + printer + ", the job plans for " +
                                         job + " (choose the printer model with print.printer_model)");
  };
  if (id.dpi_x != model.dpi_x || id.dpi_y != model.dpi_y)
    return mismatch("prints at", std::to_string(id.dpi_x) + "x" + std::to_string(id.dpi_y) + " dpi",
                    std::to_string(model.dpi_x) + "x" + std::to_string(model.dpi_y) + " dpi");
  if (id.nozzles_per_ink != model.nozzles_per_ink)
    return mismatch("has", std::to_string(id.nozzles_per_ink) + " nozzles per ink",
                    std::to_string(model.nozzles_per_ink));
  if (id.bits_per_pixel != model.bits_per_pixel)
    return mismatch("takes", std::to_string(id.bits_per_pixel) + " bits per pixel",
                    std::to_string(model.bits_per_pixel));
  if (id.inks.size() != model.inks.size())
    return mismatch("has", std::to_string(id.inks.size()) + " inks", std::to_string(model.inks.size()));
  for (size_t i = 0; i < id.inks.size(); ++i)
    if (id.inks[i] != model.inks[i].name) return mismatch("has ink", id.inks[i], model.inks[i].name);
  return {};
}

Result<PrinterPreflight> preflight_printer(PrinterChoice printer, const device::PrinterModel& model) {
  PrinterPreflight out;
  PrinterConfig cfg;
  cfg.printer = printer;
  cfg.use_gpio = false;  // a handshake only: the cutting table's lines stay with the print stage
  cfg.open_timeout = std::chrono::milliseconds(1000);
  auto session = PrintSession::open(cfg);
  if (!session) {
    out.note = session.error().message;
    return out;
  }
  if (auto st = check_printer(model, (*session)->printer()); !st) return fail(st.error());
  out.reached = true;
  return out;
}

}  // namespace tp::host
