// device/firmware/controller_engine.cpp: the controller's print engine: feeds and carriage passes
// with modelled timing, laying swaths on the fabric, cue holds and the end of a job.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>

#include "device/firmware/controller.h"
#include "device/firmware/print_timing.h"
#include "device/swath/packbits.h"

namespace tp::device {

// Drops in one byte of packed pixels at `bpp` bits per pixel: how many fields are non-zero.
std::array<std::uint8_t, 256> drop_count_table(int bpp) {
  std::array<std::uint8_t, 256> t{};
  const unsigned mask = (1u << bpp) - 1;
  for (unsigned b = 0; b < 256; ++b)
    for (int shift = 0; shift < 8; shift += bpp) t[b] += ((b >> shift) & mask) ? 1 : 0;
  return t;
}

namespace {

// Bound on engine steps per advance() call, so a bug cannot spin the simulator forever.
constexpr int kMaxStepsPerAdvance = 1 << 20;

}  // namespace

std::int64_t PrinterController::next_event_us() const { return op_ == OpKind::kNone ? INT64_MAX : op_end_us_; }

void PrinterController::start_op(OpKind kind, double modelled_s, std::int64_t now_us) {
  op_ = kind;
  op_time_s_ = modelled_s;
  op_end_us_ = options_.speed > 0 ? now_us + std::llround(modelled_s / options_.speed * 1e6) : now_us;
  status_dirty_ = true;
}

void PrinterController::check_cues() {
  if (cue_waiting_ != 0 || !job_active_) return;
  // The earliest unreached cue the fabric has passed stops the feed until the host fires it.
  Cue* next = nullptr;
  for (auto& [id, cue] : cues_)
    if (!cue.reached && cue.msg.position_um <= fabric_pos_um_ && (!next || cue.msg.position_um < next->msg.position_um))
      next = &cue;
  if (!next) return;
  next->reached = true;
  cue_waiting_ = next->msg.cue_id;
  status_dirty_ = true;
  emit(FirmwareEventKind::kCueReached, 0, cue_waiting_, std::string(to_string(next->msg.kind)));
}

void PrinterController::print_front() {
  BufferedSwath& s = buffer_.front();
  const SwathHeader& h = s.msg.header;
  std::span<const std::uint8_t> raw = s.data;
  if (h.compression == SwathCompression::kPackBits) {
    raw_.clear();
    if (auto st = packbits_decode(s.data, h.raw_bytes, raw_); !st) {
      // The CRC matched, so the host compressed it wrongly: stop rather than print garbage.
      emit(FirmwareEventKind::kReject, h.index, 0, "swath " + std::to_string(h.index) + ": " + st.error().message);
      raise_fault(PrinterCondition::kSwathCorrupt);
      return;
    }
    raw = raw_;
  }
  // Count drops per ink, as a real printer's ink accounting does.
  const std::size_t channel_bytes = static_cast<std::size_t>(swath_row_bytes(h)) * h.rows;
  for (std::size_t c = 0; c < h.channels && c < drops_per_ink_.size(); ++c) {
    std::uint64_t n = 0;
    for (std::uint8_t b : raw.subspan(c * channel_bytes, channel_bytes)) n += drop_table_[b];
    drops_per_ink_[c] += n;
  }
  // The swath names its fabric row; the feeds say where the head is. Their difference is the
  // nozzle the swath starts at, which must stay within the head for the ink to land there.
  const std::int64_t head_row = std::llround(static_cast<double>(fabric_pos_um_) * model_.dpi_y / 25400.0);
  const std::int64_t offset = h.first_row - head_row;
  const std::int64_t span = static_cast<std::int64_t>(model_.nozzles_per_ink) * model_.nozzle_pitch_rows;
  if (swaths_printed_ == 0 || offset < head_offset_min_) head_offset_min_ = offset;
  if (swaths_printed_ == 0 || offset > head_offset_max_) head_offset_max_ = offset;
  if (head_offset_max_ - head_offset_min_ > span) ++row_mismatches_;
  if (sink_) sink_->swath_printed(h, raw, h.first_row);
  printed_next_ = h.index + 1;
  printed_fabric_um_ = fabric_pos_um_;
  ++swaths_printed_;
  const std::uint32_t index = h.index;
  buffer_.pop_front();
  emit(FirmwareEventKind::kSwathPrinted, index);
}

void PrinterController::complete_op() {
  print_time_s_ += op_time_s_;
  const OpKind done = op_;
  op_ = OpKind::kNone;
  status_dirty_ = true;
  if (done == OpKind::kPrint) {
    print_front();
    return;
  }
  fabric_pos_um_ += op_feed_um_;
  feed_travel_um_ += op_feed_um_;
  emit(FirmwareEventKind::kFeed, 0, 0, std::to_string(op_feed_um_));
  check_cues();
}

void PrinterController::advance(std::int64_t now_us) {
  now_us_ = std::max(now_us_, now_us);
  for (int step = 0; step < kMaxStepsPerAdvance; ++step) {
    if (op_ != OpKind::kNone) {
      if (now_us_ < op_end_us_) break;
      complete_op();
      continue;
    }
    if (!job_active_ || fault_ != PrinterCondition::kNone || cue_waiting_ != 0 || pause_mask_ != 0) break;
    if (!buffer_.empty()) {
      BufferedSwath& front = buffer_.front();
      if (!front.fed) {
        front.fed = true;
        if (front.msg.header.feed_before_um > 0) {
          op_feed_um_ = front.msg.header.feed_before_um;
          start_op(OpKind::kFeed, feed_time_s(model_, op_feed_um_), now_us_);
          continue;
        }
      }
      if (front.feed_only) {
        buffer_.pop_front();
        continue;
      }
      emit(FirmwareEventKind::kSwathPrinting, front.msg.header.index);
      // The observer may inject a fault, a pause or the loss of the job right here.
      if (!job_active_ || buffer_.empty() || fault_ != PrinterCondition::kNone || pause_mask_ != 0) break;
      start_op(OpKind::kPrint, pass_time_s(model_, buffer_.front().msg.header), now_us_);
      continue;
    }
    const bool all_printed = end_requested_ && !rx_swath_ && swath_next_ >= end_.swath_count &&
                             printed_next_ >= end_.swath_count;
    if (!all_printed) break;
    if (!final_feed_done_) {
      final_feed_done_ = true;
      if (end_.final_feed_um > 0) {
        op_feed_um_ = end_.final_feed_um;
        start_op(OpKind::kFinalFeed, feed_time_s(model_, op_feed_um_), now_us_);
      }
      continue;
    }
    emit(FirmwareEventKind::kJobEnd, printed_next_, 0, "completed");
    finish_job(JobOutcome::kCompleted);
    break;
  }
  note_state();
}

JobReportMsg PrinterController::report() const {
  JobReportMsg r;
  r.job_id = job_.job_id;
  r.name = job_.name;
  r.condition = fault_;
  r.first_swath = report_first_swath_;
  r.swaths_printed = swaths_printed_;
  r.feed_travel_um = feed_travel_um_;
  r.print_time_us = static_cast<std::uint64_t>(std::llround(print_time_s_ * 1e6));
  r.cues_fired = cues_fired_;
  r.overruns = overruns_;
  r.drops_per_ink = drops_per_ink_;
  return r;
}

void PrinterController::finish_job(JobOutcome outcome, bool send_report) {
  JobReportMsg r = report();
  r.outcome = outcome;
  last_report_ = r;
  last_job_id_ = job_.job_id;
  last_outcome_ = outcome;
  last_printed_next_ = printed_next_;
  last_printed_fabric_um_ = printed_fabric_um_;
  last_fabric_pos_um_ = fabric_pos_um_;
  if (send_report) {
    std::vector<std::uint8_t> payload;
    encode(r, payload);
    queue_frame(MessageType::kJobReport, payload);
  }
  job_active_ = false;
  fault_ = PrinterCondition::kNone;
  cue_waiting_ = 0;
  cues_.clear();
  buffer_.clear();
  rx_swath_.reset();
  ignoring_swath_.reset();
  op_ = OpKind::kNone;
  status_dirty_ = true;
  if (sink_) sink_->job_finished(r);
  note_state();
}

}  // namespace tp::device
