// rip/swath/pass_plan.cpp: the multi-pass weave arithmetic.
#include "rip/swath/pass_plan.h"

#include <algorithm>
#include <numeric>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

namespace {
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }
}  // namespace

Result<PassPlan> make_pass_plan(const device::PrinterModel& printer, int passes) {
  const int nozzles = printer.nozzles_per_ink, pitch = printer.nozzle_pitch_rows;
  if (nozzles < 1 || pitch < 1)
    return fail(ErrorCode::kSwath, fmt::format("printer '{}': nozzles_per_ink {} and nozzle_pitch_rows {} must be >= 1",
                                               printer.name, nozzles, pitch));
  if (passes < 1 || passes > nozzles)
    return fail(ErrorCode::kSwath, fmt::format("passes {} must be between 1 and the printer's {} nozzles per ink",
                                               passes, nozzles));
  // Drop nozzles from the end of the row until the weave closes; printers with pitch 1 use all.
  for (int n = nozzles - nozzles % passes; n >= passes; n -= passes) {
    if (std::gcd(n / passes, pitch) == 1) return PassPlan{passes, n, pitch, n / passes};
  }
  return fail(ErrorCode::kSwath, fmt::format("printer '{}': no weave for {} passes with {} nozzles at pitch {}",
                                             printer.name, passes, nozzles, pitch));
}

std::int64_t first_pass(const PassPlan& plan) {
  // Smallest k with k*f + (N-1)*p >= 0.
  return ceil_div(-static_cast<std::int64_t>(plan.nozzles_used - 1) * plan.nozzle_pitch_rows, plan.feed_rows);
}

std::int64_t last_pass(const PassPlan& plan, std::int64_t height_rows) {
  return floor_div(height_rows - 1, plan.feed_rows);
}

PassRows rows_of_pass(const PassPlan& plan, std::int64_t pass, std::int64_t height_rows) {
  const std::int64_t origin = pass_origin_row(plan, pass), p = plan.nozzle_pitch_rows;
  std::int64_t n_lo = origin >= 0 ? 0 : ceil_div(-origin, p);
  std::int64_t n_hi = std::min<std::int64_t>(plan.nozzles_used - 1, floor_div(height_rows - 1 - origin, p));
  PassRows r;
  if (n_hi < n_lo) return r;
  r.first_nozzle = static_cast<int>(n_lo);
  r.first_row = origin + n_lo * p;
  r.rows = static_cast<int>(n_hi - n_lo + 1);
  return r;
}

}  // namespace tp::rip
