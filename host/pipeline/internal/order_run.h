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
  int first_piece = 0;                   ///< its first piece in the order's merged pattern
  double x_offset_mm = 0;                ///< where its garment sits in the order's merged garment
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

/// Copy `c` alone on its size's body: its pieces of the order's merged garment (the others
/// emptied, as geometry::garment_without does), moved back by its offset.
[[nodiscard]] geometry::Garment order_copy_garment(const geometry::Garment& merged, const OrderCopyRun& c);

/// Writes each size's `sizes/<size>/garment-print-{front,side,back}.png` (its first copy wearing
/// its print, on the size's body; `report.sizes[].print_previews`) and copies the base size's to
/// the job's own `garment-print-*.png`, whose names it returns.
[[nodiscard]] Result<std::vector<std::string>> write_order_print_previews(PipelineState& ps,
                                                                          const geometry::Garment& worn, double dpi);

/// report.order's marker and print figures, once every stage has run (run_job).
void finish_order_report(nlohmann::json& report);

}  // namespace tp::host::internal
