// device/firmware/print_timing.h: how long a carriage pass and a fabric feed take on a printer
// model, so the simulator reports realistic print times.
#pragma once

#include <cstdint>

#include "device/model/printer_model.h"
#include "device/swath/swath.h"

namespace tp::device {

/// Carriage travel beyond the printed width on each side: acceleration ramp plus the spread of
/// the ink rows across the head.
inline constexpr double kCarriageRampMm = 40.0;
/// Time to reverse the carriage and settle before the next pass.
inline constexpr double kCarriageTurnaroundS = 0.12;
/// Settling time after a fabric feed before the next pass.
inline constexpr double kFeedSettleS = 0.05;

/// Seconds one carriage pass over `swath` takes on `model`.
double pass_time_s(const PrinterModel& model, const SwathHeader& swath);

/// Seconds to advance the fabric by `feed_um` on `model` (0 for no feed).
double feed_time_s(const PrinterModel& model, std::int64_t feed_um);

}  // namespace tp::device
