// host/pipeline/stage_intake.cpp: records what the job asks for in the report, and checks the
// connected printer against the job's printer model before any stage works for it.
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/printer_check.h"
#include "host/pipeline/printer_model.h"

namespace tp::host::internal {

Status stage_intake(PipelineState& ps) {
  const Job& j = ps.job;
  std::string source = j.garment.pattern ? "pattern" : j.garment.garment_mesh ? "garment_mesh" : "sample";
  ps.report["intake"] = {{"garment_source", source},
                         {"body", j.garment.body_kind},
                         {"design_layers", j.design.size()},
                         {"fabric_width_mm", j.marker.fabric_width_mm},
                         {"dpi", j.print.dpi},
                         {"passes", j.print.passes},
                         {"printer", to_string(effective_printer(j.print.printer, ps.options.printer_override))},
                         {"resume_after_swath", ps.options.resume_after_swath}};
  // A job planned for another printer fails here, not after its garment, design and RIP stages.
  const PrinterChoice printer = effective_printer(j.print.printer, ps.options.printer_override);
  if (printer == PrinterChoice::kNone) return {};
  auto model = job_printer_model(j);
  if (!model) return fail(model.error());
  auto preflight = preflight_printer(printer, *model);
  if (!preflight) return fail(preflight.error());
  ps.report["intake"]["printer_checked"] = preflight->reached;
  if (!preflight->reached) ps.report["intake"]["printer_not_checked_because"] = preflight->note;
  return {};
}

}  // namespace tp::host::internal
