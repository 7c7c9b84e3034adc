// rip/swath/pass_plan.h: which fabric rows and columns each carriage pass prints (single-pass and
// interleaved multi-pass), from the printer's head geometry.
#pragma once

#include <cstdint>

#include "device/model/printer_model.h"
#include "rip/common/error.h"

namespace tp::rip {

/// The weave of a print mode.
///
/// Pass k (any integer; the fabric advances `feed_rows` between consecutive passes) puts nozzle n
/// (0 <= n < nozzles_used) over fabric row k * feed_rows + n * nozzle_pitch_rows. With
/// feed_rows = nozzles_used / passes and gcd(feed_rows, pitch) = 1 every fabric row lies under the
/// head in exactly `passes` passes; the v-th of them (visit v = passes - 1 - n / feed_rows) prints
/// the columns x with (x + row) mod passes == v. So each pass prints a subset of rows (one nozzle
/// block per visit) and of columns, and every pixel is printed exactly once.
struct PassPlan {
  int passes = 1;
  int nozzles_used = 0;        ///< nozzles of each ink row in use (a multiple of passes)
  int nozzle_pitch_rows = 1;   ///< rows between adjacent nozzles
  int feed_rows = 0;           ///< fabric advance between passes, in rows at dpi_y
};

/// Plans `passes` passes for `printer`. Uses the most nozzles n <= nozzles_per_ink with
/// n % passes == 0 and gcd(n / passes, pitch) == 1.
/// Fails (kSwath) when passes < 1 or > nozzles, or no nozzle count satisfies the weave.
[[nodiscard]] Result<PassPlan> make_pass_plan(const device::PrinterModel& printer, int passes);

/// The first pass that reaches fabric row 0 (its last nozzle is on row >= 0).
std::int64_t first_pass(const PassPlan& plan);
/// The last pass that reaches a row below `height_rows` (its nozzle 0 is on row < height_rows).
std::int64_t last_pass(const PassPlan& plan, std::int64_t height_rows);

/// The rows of pass k inside [0, height_rows): nozzles first_nozzle .. first_nozzle + rows - 1.
struct PassRows {
  std::int64_t first_row = 0;
  int first_nozzle = 0;
  int rows = 0;
};
PassRows rows_of_pass(const PassPlan& plan, std::int64_t pass, std::int64_t height_rows);

/// Visit index (0 = first time the row is under the head) of nozzle n.
inline int visit_of_nozzle(const PassPlan& plan, int nozzle) {
  return plan.passes - 1 - nozzle / plan.feed_rows;
}

/// The column phase printed on fabric row `row` at visit `visit`: columns x with
/// x mod passes == column_phase.
inline int column_phase(const PassPlan& plan, std::int64_t row, int visit) {
  const std::int64_t p = plan.passes;
  return static_cast<int>((((visit - row) % p) + p) % p);
}

/// The fabric row a pass's feed has reached: the row under nozzle 0 (may be negative).
inline std::int64_t pass_origin_row(const PassPlan& plan, std::int64_t pass) {
  return pass * plan.feed_rows;
}

}  // namespace tp::rip
