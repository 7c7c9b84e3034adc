// device/firmware/print_timing.cpp: carriage and feed timing from the printer model's speeds.
#include "device/firmware/print_timing.h"

#include <algorithm>
#include <cmath>

namespace tp::device {

double pass_time_s(const PrinterModel& model, const SwathHeader& swath) {
  const double width_mm = swath.width_px * 25.4 / model.dpi_x;
  double head_span_mm = 0;
  for (const auto& ink : model.inks) head_span_mm = std::max(head_span_mm, std::abs(ink.head_offset_x_mm));
  const double travel_mm = width_mm + head_span_mm + 2 * kCarriageRampMm;
  return travel_mm / model.carriage_speed_mm_s + kCarriageTurnaroundS;
}

double feed_time_s(const PrinterModel& model, std::int64_t feed_um) {
  if (feed_um <= 0) return 0;
  return static_cast<double>(feed_um) / 1000.0 / model.feed_speed_mm_s + kFeedSettleS;
}

}  // namespace tp::device
