// host/pipeline/internal/order_run.h: the per-size and per-copy pipeline states of an order job
// and the order's versions of the pattern, mesh, garment and design stages.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "host/job/copy_text.h"
#include "host/pipeline/internal/pipeline_state.h"

namespace tp::host::internal {

/// One size: its own job (size, pattern, body), sewn once for all its copies.
struct OrderSizeRun {
  OrderSizeSpec spec;
  Job job;
  RunOptions options;
  nlohmann::json report = nlohmann::json::object();
  std::unique_ptr<PipelineState> ps;
  std::string stem;  ///< the size as a file name
};

/// One garment of the order: a copy of a size, with its own text and labels.
struct OrderCopyRun {
  int copy = 0;     ///< 1-based, over the whole order
  size_t size = 0;  ///< index into OrderRun::sizes
  CopyFields fields;
  Job job;
  nlohmann::json report = nlohmann::json::object();
  std::unique_ptr<PipelineState> ps;
  std::vector<std::string> piece_names;  ///< names in the order's merged pattern
};

struct OrderRun {
  std::vector<std::unique_ptr<OrderSizeRun>> sizes;
  std::vector<std::shared_ptr<OrderCopyRun>> copies;
  size_t base = 0;  ///< index of the base size
};

[[nodiscard]] Status stage_order_pattern(PipelineState& ps);
[[nodiscard]] Status stage_order_mesh(PipelineState& ps);
[[nodiscard]] Status stage_order_garment(PipelineState& ps);
[[nodiscard]] Status stage_order_design(PipelineState& ps);

/// report.order's marker and print figures, once every stage has run (run_job).
void finish_order_report(nlohmann::json& report);

}  // namespace tp::host::internal
