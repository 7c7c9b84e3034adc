// host/pipeline/printer_model.h: the printer a job plans its swaths for.
#pragma once

#include "device/model/printer_model.h"
#include "host/common/error.h"
#include "host/job/job.h"

namespace tp::host {

/// The job's printer model (its print.printer_model file, else the built-in model) in the print
/// mode the job asks for: print.dpi across and along the fabric. Fails (kValidation) naming the
/// field when the model file is unreadable or invalid.
[[nodiscard]] Result<device::PrinterModel> job_printer_model(const Job& job);

}  // namespace tp::host
