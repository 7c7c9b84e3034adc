// host/pipeline/stages_pending.cpp: stages whose layer APIs are still landing (removed as each lands).
#include "host/pipeline/internal/pipeline_state.h"

namespace tp::host::internal {

namespace {
Status pending(const char* what) { return fail(ErrorCode::kPipeline, std::string(what) + " is not integrated yet"); }
}  // namespace

Status stage_pattern(PipelineState&) { return pending("pattern loading"); }
Status stage_mesh(PipelineState&) { return pending("meshing"); }
Status stage_garment(PipelineState&) { return pending("garment building"); }
Status stage_design(PipelineState&) { return pending("design"); }
Status stage_marker(PipelineState&) { return pending("nesting"); }
Status stage_print(PipelineState&) { return pending("printing"); }
Status stage_outputs(PipelineState&) { return pending("outputs"); }

}  // namespace tp::host::internal
