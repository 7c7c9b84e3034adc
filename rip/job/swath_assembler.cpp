// rip/job/swath_assembler.cpp: pass masks, swath trimming, PackBits per row and the feed bookkeeping.
#include "rip/job/internal/swath_assembler.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "device/swath/packbits.h"
#include "rip/common/internal/cpu_clock.h"
#include "rip/common/memory.h"

namespace tp::rip {

namespace {
using Clock = std::chrono::steady_clock;
constexpr std::int64_t kUmPerInch = 25400;
}  // namespace

SwathAssembler::SwathAssembler(const PassPlan& plan, const device::PrinterModel& printer,
                               const RipSettings& settings, int width_px, std::int64_t height_px,
                               int bits_per_pixel, const ScreenedWindow& window, int workers)
    : plan_(plan), settings_(settings), dpi_y_(printer.dpi_y), width_px_(width_px), bits_(bits_per_pixel),
      height_px_(height_px), window_(window) {
  first_pass_ = first_pass(plan);
  next_pass_ = first_pass_;
  last_pass_ = last_pass(plan, height_px);
  previous_position_pass_ = first_pass_;
  // Column masks: phase ph keeps the codes of columns x with x mod passes == ph.
  if (plan.passes > 1) {
    const int row_bytes = window.row_bytes(), per_byte = 8 / bits_;
    masks_.assign(static_cast<size_t>(plan.passes), std::vector<std::uint8_t>(static_cast<size_t>(row_bytes) + 8, 0));
    for (int ph = 0; ph < plan.passes; ++ph)
      for (int x = ph; x < row_bytes * per_byte; x += plan.passes)
        masks_[ph][static_cast<size_t>(x / per_byte)] |=
            static_cast<std::uint8_t>(((1 << bits_) - 1) << (8 - bits_ - (x % per_byte) * bits_));
  }
  channel_out_.resize(static_cast<size_t>(window.channels()));
  channel_len_.assign(static_cast<size_t>(window.channels()), 0);
  scratch_.assign(static_cast<size_t>(workers), std::vector<std::uint8_t>(static_cast<size_t>(window.row_bytes()) + 8));
  swath_s_.assign(static_cast<size_t>(workers), 0.0);
}

std::int64_t SwathAssembler::position_um(std::int64_t pass) const {
  // Cumulative from the job's first pass, rounded once, so feeds never drift.
  const std::int64_t rows = (pass - first_pass_) * plan_.feed_rows;
  return (rows * kUmPerInch + dpi_y_ / 2) / dpi_y_;
}

std::int64_t SwathAssembler::lowest_needed_row() const { return pass_origin_row(plan_, next_pass_); }

void SwathAssembler::build_channel(const PassRows& pr, int first_byte, int row_bytes,
                                   int channel, int worker) {
  const double t0 = thread_cpu_seconds();
  // The buffer keeps its size between swaths (no re-zeroing); the used length is tracked apart.
  std::vector<std::uint8_t>& out = channel_out_[static_cast<size_t>(channel)];
  const bool packbits = settings_.compression == device::SwathCompression::kPackBits;
  const size_t worst =
      static_cast<size_t>(pr.rows) * (packbits ? device::packbits_max_size(static_cast<size_t>(row_bytes)) : row_bytes);
  if (out.size() < worst) out.resize(worst);
  size_t used = 0;
  std::uint8_t* tmp = scratch_[static_cast<size_t>(worker)].data();
  for (int r = 0; r < pr.rows; ++r) {
    const std::int64_t y = pr.first_row + static_cast<std::int64_t>(r) * plan_.nozzle_pitch_rows;
    const std::uint8_t* src = window_.row(y, channel) + first_byte;
    if (plan_.passes > 1) {
      // This nozzle's visit decides which columns of the row it prints.
      const int visit = visit_of_nozzle(plan_, pr.first_nozzle + r);
      const std::uint8_t* mask = masks_[static_cast<size_t>(column_phase(plan_, y, visit))].data() + first_byte;
      for (int i = 0; i < row_bytes; ++i) tmp[i] = src[i] & mask[i];
      src = tmp;
    }
    if (packbits) {
      used += device::packbits_encode({src, static_cast<size_t>(row_bytes)}, out.data() + used);
    } else {
      std::memcpy(out.data() + used, src, static_cast<size_t>(row_bytes));
      used += static_cast<size_t>(row_bytes);
    }
  }
  channel_len_[static_cast<size_t>(channel)] = used;
  swath_s_[static_cast<size_t>(worker)] += thread_cpu_seconds() - t0;
}

Status SwathAssembler::emit_ready(std::int64_t rows_done, ThreadPool& pool, const SwathSink& sink, RipStats& stats) {
  const int nc = window_.channels(), per_byte = 8 / bits_;
  for (; next_pass_ <= last_pass_; ++next_pass_) {
    const std::int64_t k = next_pass_;
    const PassRows pr = rows_of_pass(plan_, k, height_px_);
    if (pr.rows > 0 && pr.first_row + static_cast<std::int64_t>(pr.rows - 1) * plan_.nozzle_pitch_rows >= rows_done)
      break;  // not all rows screened yet
    if (pr.rows == 0) continue;
    // Inked byte range over the pass's rows.
    int first = window_.row_bytes(), last = -1;
    for (int r = 0; r < pr.rows; ++r) {
      const std::int64_t y = pr.first_row + static_cast<std::int64_t>(r) * plan_.nozzle_pitch_rows;
      first = std::min(first, window_.extent_first(y));
      last = std::max(last, window_.extent_last(y));
    }
    const bool blank = first > last;
    if (blank && settings_.skip_blank_swaths) continue;
    if (blank) first = last = 0;

    device::Swath swath;
    device::SwathHeader& h = swath.header;
    h.index = next_index_++;
    h.pass = static_cast<std::uint16_t>(((k % plan_.passes) + plan_.passes) % plan_.passes);
    h.direction = settings_.bidirectional && (h.index % 2 == 1) ? device::CarriageDirection::kRightToLeft
                                                                : device::CarriageDirection::kLeftToRight;
    h.first_row = pr.first_row;
    h.row_step = static_cast<std::uint16_t>(plan_.nozzle_pitch_rows);
    h.rows = static_cast<std::uint32_t>(pr.rows);
    h.x_start_px = first * per_byte;
    h.width_px = static_cast<std::uint32_t>(std::min((last + 1) * per_byte, width_px_) - h.x_start_px);
    h.channels = static_cast<std::uint8_t>(nc);
    h.bits_per_pixel = static_cast<std::uint8_t>(bits_);
    h.feed_before_um = static_cast<std::uint32_t>(position_um(k) - position_um(previous_position_pass_));
    h.compression = settings_.compression;
    const int row_bytes = static_cast<int>(device::swath_row_bytes(h));
    h.raw_bytes = static_cast<std::uint32_t>(static_cast<std::uint64_t>(row_bytes) * pr.rows * nc);
    previous_position_pass_ = k;
    stats.swaths = next_index_;
    if (h.index < settings_.first_swath_index) continue;  // resuming: computed, not sent

    pool.parallel_for(nc, [&](int c, int worker) { build_channel(pr, first, row_bytes, c, worker); });
    size_t total = 0;
    for (size_t len : channel_len_) total += len;
    // Appended, not resized and copied over: no zero fill of tens of megabytes.
    swath.data.reserve(total);
    advise_huge_pages(swath.data.data(), total);
    for (size_t c = 0; c < channel_out_.size(); ++c)
      swath.data.insert(swath.data.end(), channel_out_[c].begin(), channel_out_[c].begin() + static_cast<std::ptrdiff_t>(channel_len_[c]));
    stats.raw_bytes += h.raw_bytes;
    stats.compressed_bytes += swath.data.size();
    ++stats.swaths_sent;

    const std::uint32_t index = h.index;
    auto t0 = Clock::now();
    Status s = sink(std::move(swath));
    stats.sink_s += std::chrono::duration<double>(Clock::now() - t0).count();
    if (!s) return std::unexpected(s.error().with_context("swath " + std::to_string(index)));
  }
  stats.swath_cpu_s = 0;
  for (double v : swath_s_) stats.swath_cpu_s += v;
  return {};
}

}  // namespace tp::rip
