// host/pipeline/stage_intake.cpp: records what the job asks for in the report.
#include "host/pipeline/internal/pipeline_state.h"

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
  return {};
}

}  // namespace tp::host::internal
