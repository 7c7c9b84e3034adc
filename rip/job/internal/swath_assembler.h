// rip/job/internal/swath_assembler.h: cuts screened rows into printhead swaths as passes complete.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/common/thread_pool.h"
#include "device/model/printer_model.h"
#include "device/swath/swath.h"
#include "rip/job/internal/screened_window.h"
#include "rip/job/rip_job.h"
#include "rip/swath/pass_plan.h"

namespace tp::rip {

/// Emits the swaths of passes first_pass .. last_pass in order, each once all its rows are
/// screened: rows at the head's nozzle pitch, columns masked to the pass's share, trimmed to the
/// inked byte range, compressed per row, with the feed since the previous swath.
class SwathAssembler {
 public:
  SwathAssembler(const PassPlan& plan, const device::PrinterModel& printer, const RipSettings& settings,
                 int width_px, std::int64_t height_px, int bits_per_pixel, const ScreenedWindow& window,
                 int workers);

  /// Emits every pass whose rows all lie below `rows_done`. Fails with the sink's error.
  [[nodiscard]] Status emit_ready(std::int64_t rows_done, ThreadPool& pool, const SwathSink& sink, RipStats& stats);

  /// The lowest fabric row a pass not yet emitted still needs (rows below may be overwritten).
  std::int64_t lowest_needed_row() const;
  bool done() const { return next_pass_ > last_pass_; }

 private:
  void build_channel(const PassRows& rows, int first_byte, int row_bytes, int channel, int worker);
  std::int64_t position_um(std::int64_t pass) const;

  PassPlan plan_;
  const RipSettings& settings_;
  int dpi_y_;
  int width_px_, bits_;
  std::int64_t height_px_;
  const ScreenedWindow& window_;
  std::int64_t first_pass_, next_pass_, last_pass_;
  std::int64_t previous_position_pass_;
  std::uint32_t next_index_ = 0;
  std::vector<std::vector<std::uint8_t>> masks_;          ///< per column phase, a full row of masks
  std::vector<std::vector<std::uint8_t>> channel_out_;    ///< per channel, this swath's encoded rows
  std::vector<size_t> channel_len_;                       ///< bytes used in channel_out_
  std::vector<std::vector<std::uint8_t>> scratch_;        ///< per worker, one masked row
  std::vector<double> swath_s_;                           ///< per worker CPU seconds
};

}  // namespace tp::rip
