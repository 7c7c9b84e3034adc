// host/pipeline/printer_model.cpp: the printer a job plans its swaths for.
#include "host/pipeline/printer_model.h"

#include "device/model/printer_model_file.h"

namespace tp::host {

Result<device::PrinterModel> job_printer_model(const Job& job) {
  device::PrinterModel model;
  if (job.print.printer_model) {
    auto m = device::load_printer_model(*job.print.printer_model);
    if (!m) return fail(ErrorCode::kValidation, "job.json: /print/printer_model: " + m.error().what());
    model = *m;
  }
  model.dpi_x = model.dpi_y = job.print.dpi;
  if (auto st = device::validate_printer_model(model); !st)
    return fail(ErrorCode::kValidation, "job.json: /print/dpi: " + st.error().message);
  return model;
}

}  // namespace tp::host
