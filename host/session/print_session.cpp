// host/session/print_session.cpp: opening the printer, running a job within credits, checkpoints,
// faults, pauses and the emergency stop.
#include "host/session/print_session.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>

#include "device/protocol/recording.h"
#include "host/session/internal/session_log.h"
#include "host/session/internal/session_text.h"

namespace tp::host {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

using internal::from_device;
using internal::mm_text;

PrintSession::PrintSession(PrinterConfig config, std::unique_ptr<device::Transport> transport,
                           std::unique_ptr<drivers::GpioLines> gpio)
    : config_(std::move(config)), transport_(std::move(transport)), gpio_(std::move(gpio)) {}

PrintSession::~PrintSession() {
  if (active_) (void)abort_job("print session closed before the job ended");
}

Result<std::unique_ptr<PrintSession>> PrintSession::open(const PrinterConfig& config) {
  if (config.printer == PrinterChoice::kNone)
    return fail(ErrorCode::kInvalidArgument, "printer 'none': there is no printer to open");
  if (needs_printsim(config.printer))
    return fail(ErrorCode::kPrinter,
                "printer 'sim' is the simulated printer: run the job with `printctl run` (which starts printsim) "
                "or under `printsim run -- <command>`");
  auto usb = drivers::UsbTransport::open(config.usb, config.open_timeout);
  if (!usb) return fail(ErrorCode::kPrinter, "opening the printer: " + usb.error().message);
  std::unique_ptr<drivers::GpioLines> gpio;
  if (config.use_gpio) {
    auto g = drivers::GpioLines::open(config.gpio);
    if (!g) return fail(ErrorCode::kPrinter, "opening the cutting table: " + g.error().message);
    gpio = std::move(*g);
  }
  return open_with(std::move(*usb), config, std::move(gpio));
}

Result<std::unique_ptr<PrintSession>> PrintSession::open_with(std::unique_ptr<device::Transport> transport,
                                                               const PrinterConfig& config,
                                                               std::unique_ptr<drivers::GpioLines> gpio) {
  std::unique_ptr<PrintSession> s(new PrintSession(config, std::move(transport), std::move(gpio)));
  if (auto c = s->connect(); !c) return fail(c.error());
  return s;
}

Status PrintSession::connect() {
  if (config_.wire_recording && !recorder_) {
    auto r = device::RecordingTransport::create(*transport_, *config_.wire_recording);
    if (!r) return fail(from_device(r.error(), "wire recording"));
    recorder_ = std::move(*r);
  }
  if (!link_) link_ = std::make_unique<device::HostLink>(recorder_ ? *recorder_ : *transport_, config_.link);
  auto id = link_->handshake();
  if (!id) return fail(from_device(id.error(), transport_->describe()));
  identity_ = *id;
  if (identity_.inks.empty() || identity_.swath_slots == 0)
    return fail(ErrorCode::kPrinter, transport_->describe() + ": printer reports no inks or no swath buffer");
  session_log()->info("{}: printer '{}' ({}), protocol {}, {} inks, {}x{} dpi, {} swath slots", transport_->describe(),
                      identity_.model, identity_.firmware, identity_.protocol_version, identity_.inks.size(),
                      identity_.dpi_x, identity_.dpi_y, identity_.swath_slots);
  return {};
}

const device::IdentifyMsg& PrintSession::printer() const { return identity_; }

std::string PrintSession::describe() const { return transport_->describe(); }

void PrintSession::on_swath_acked(std::function<void(std::uint32_t)> callback) { on_acked_ = std::move(callback); }

void PrintSession::on_swath_printed(std::function<void(std::uint32_t, std::int64_t)> callback) {
  on_printed_ = std::move(callback);
}

std::string PrintSession::job_where() const {
  const device::StatusMsg* s = link_ ? link_->status() : nullptr;
  return " (job " + std::to_string(job_.job_id) + " '" + job_.name + "': swaths below " + std::to_string(acked_next_) +
         " acknowledged, below " + std::to_string(printed_next_) + " printed" +
         (s ? ", fabric at " + mm_text(s->fabric_pos_um) : std::string()) + ")";
}

Status PrintSession::fail_job(ErrorCode code, const std::string& message) {
  const std::string where = job_where();
  if (active_) {
    active_ = false;
    // Clear the printer for the next job; the error below is what matters if this fails too.
    device::AbortMsg abort{message};
    if (link_->send_msg(device::MessageType::kAbort, abort)) (void)link_->drain(milliseconds(2000));
  }
  session_log()->error("{}{}", message, where);
  return fail(code, message + where);
}

Status PrintSession::begin_job(const JobStart& job) {
  if (active_) return fail(ErrorCode::kInvalidArgument, "begin_job: job " + std::to_string(job_.job_id) + " is still open");
  // The printer reports job id 0 as "no job", so a job numbered 0 could never be seen to finish.
  if (job.job_id == 0) return fail(ErrorCode::kInvalidArgument, "begin_job: job id 0 is reserved for \"no job\"");
  job_ = job;
  acked_next_ = printed_next_ = swath_count_ = next_send_ = job.first_swath;
  planned_end_um_ = 0;
  ending_ = false;
  finished_on_printer_ = false;
  reopen_seq_ = 0;
  unprinted_.clear();
  reattach_held_until_ = 0;
  reattach_held_bytes_ = 0;
  feed_fix_swath_.reset();
  lost_at_um_.reset();
  cues_.clear();
  cues_sent_ = 0;
  stats_ = SessionStats{};
  // Ask first: the printer may still hold this job, or remember how it ended.
  auto st = link_->query_status(milliseconds(5000));
  if (!st) return fail(from_device(st.error(), "job_begin"));
  (void)link_->take_reject();
  return attach_or_open(*st);
}

Status PrintSession::queue_cue(device::CueKind kind, std::int64_t position_um, std::int32_t x_um) {
  if (!active_) return fail(ErrorCode::kInvalidArgument, "queue_cue: no job open");
  CueRecord c;
  c.id = static_cast<std::uint32_t>(cues_.size() + 1);
  c.kind = kind;
  c.position_um = position_um;
  c.x_um = x_um;
  // Resumed after the printer lost the job: the fabric has passed the cues behind it.
  if (finished_on_printer_ || (lost_at_um_ && position_um <= *lost_at_um_)) {
    c.fired = true;
    c.fired_at_um = position_um;
    cues_.push_back(c);
    cues_sent_ = c.id;
    return {};
  }
  cues_.push_back(c);
  device::CutterCueMsg m{c.id, kind, position_um, x_um};
  for (int attempt = 0; attempt < 3; ++attempt) {
    auto s = link_->send_msg(device::MessageType::kCutterCue, m);
    if (s) {
      cues_sent_ = c.id;
      const device::StatusMsg* st = link_->status();
      if (st && st->job_id == job_.job_id && st->cue_waiting == c.id) return fire_cue(c.id, nullptr);
      return service(milliseconds(0), nullptr);
    }
    if (s.error().code != device::ErrorCode::kDisconnected) return fail(from_device(s.error(), "cue " + std::to_string(c.id)));
    if (auto r = recover(s.error()); !r) return r;
    if (cues_sent_ >= c.id) return {};  // re-registered by the recovery
  }
  return fail(ErrorCode::kPrinter, "cue " + std::to_string(c.id) + ": link kept failing");
}

device::Status PrintSession::send_wire_swath(const device::Swath& swath) {
  if (!feed_fix_swath_ || *feed_fix_swath_ != swath.header.index) return link_->send_swath(swath);
  // The planned feed starts where the previous swath was laid; the fabric stands elsewhere.
  const std::int64_t feed_um = static_cast<std::int64_t>(swath.header.feed_before_um) + feed_fix_um_;
  if (feed_um < 0)
    return device::fail(device::ErrorCode::kInvalidArgument,
                        "the printer lost the job with the fabric " + mm_text(-feed_um) + " past where swath " +
                            std::to_string(swath.header.index) +
                            " starts, and fabric cannot feed back: cut off the partial print and print the job again");
  device::Swath fixed = swath;
  fixed.header.feed_before_um = static_cast<std::uint32_t>(feed_um);
  return link_->send_swath(fixed);
}

Status PrintSession::transmit(const device::Swath& swath) {
  auto s = send_wire_swath(swath);
  if (s) return {};
  if (s.error().code != device::ErrorCode::kDisconnected)
    return fail_job(ErrorCode::kPrinter, "sending swath " + std::to_string(swath.header.index) + ": " + s.error().message);
  // The swath is already among the unprinted ones: the recovery resends it with them.
  return recover(s.error());
}

Status PrintSession::send_swath(const device::Swath& swath, const geometry::CancelToken& cancel) {
  if (!active_) return fail(ErrorCode::kInvalidArgument, "send_swath: no job open");
  const std::uint32_t idx = swath.header.index;
  const std::size_t bytes = swath.data.size();
  if (idx < next_send_) {
    // Resuming: on the fabric or in the printer already.
    swath_count_ = std::max(swath_count_, idx + 1);
    ++stats_.swaths_skipped;
    return service(milliseconds(0), &cancel);
  }
  if (idx != next_send_)
    return fail_job(ErrorCode::kInvalidArgument,
                    "swath " + std::to_string(idx) + " handed in where swath " + std::to_string(next_send_) + " was due");
  if (finished_on_printer_)
    return fail_job(ErrorCode::kPrinter, "swath " + std::to_string(idx) + " handed in, but the printer completed job " +
                                             std::to_string(job_.job_id) + " after " + std::to_string(next_send_) +
                                             " swaths: the job's plan differs from what was printed");
  if (bytes > identity_.swath_buffer_bytes)
    return fail_job(ErrorCode::kPrinter, "swath " + std::to_string(idx) + ": " + std::to_string(bytes) +
                                             " bytes exceed the printer's " +
                                             std::to_string(identity_.swath_buffer_bytes) + "-byte swath buffer");
  swath_count_ = std::max(swath_count_, idx + 1);
  ++next_send_;
  planned_end_um_ += swath.header.feed_before_um;
  // Credits: never more swaths or bytes in the printer than its buffer holds, counting the swaths a
  // re-attached printer still held (their bytes as a whole, until the last of them is printed).
  const auto t0 = Clock::now();
  for (;;) {
    const std::size_t held_slots = printed_next_ < reattach_held_until_ ? reattach_held_until_ - printed_next_ : 0;
    std::size_t held = held_slots > 0 ? reattach_held_bytes_ : 0;
    for (const auto& b : unprinted_) held += b.data.size();
    if (unprinted_.size() + held_slots < identity_.swath_slots && held + bytes <= identity_.swath_buffer_bytes) break;
    if (auto s = service(milliseconds(20), &cancel); !s) return s;
    if (!active_) return fail(ErrorCode::kPrinter, "job ended while waiting for printer credit");
  }
  stats_.credit_wait_s += std::chrono::duration<double>(Clock::now() - t0).count();
  unprinted_.push_back(swath);
  if (auto s = transmit(swath); !s) return s;
  ++stats_.swaths_sent;
  stats_.bytes_sent += bytes;
  return service(milliseconds(0), &cancel);
}

Result<JobResult> PrintSession::end_job(std::uint32_t final_feed_um, const geometry::CancelToken& cancel) {
  if (!active_) return fail(ErrorCode::kInvalidArgument, "end_job: no job open");
  ending_ = true;
  final_feed_um_ = final_feed_um;
  device::JobEndMsg m{swath_count_, final_feed_um};
  for (int attempt = 0; !finished_on_printer_; ++attempt) {
    auto s = link_->send_msg(device::MessageType::kJobEnd, m);
    if (s) break;
    if (s.error().code != device::ErrorCode::kDisconnected || attempt == 3)
      return fail(fail_job(ErrorCode::kPrinter, "job_end: " + s.error().message).error());
    if (auto r = recover(s.error()); !r) return fail(r.error());
    if (!ending_) break;  // the printer finished while we were away
  }
  const auto deadline = Clock::now() + config_.finish_timeout;
  for (;;) {
    if (auto s = service(milliseconds(20), &cancel); !s) return fail(s.error());
    const device::StatusMsg* st = link_->status();
    if (st && st->job_id != job_.job_id && st->last_job_id == job_.job_id) {
      if (st->last_outcome != device::JobOutcome::kCompleted)
        return fail(fail_job(ErrorCode::kPrinter, "printer ended the job as " +
                                                      std::string(device::to_string(st->last_outcome)))
                        .error());
      break;
    }
    if (Clock::now() > deadline)
      return fail(fail_job(ErrorCode::kPrinter, "printer did not finish within " +
                                                    std::to_string(config_.finish_timeout.count()) + " ms")
                      .error());
  }
  // The report comes unasked at the end; ask again if it was lost on the way.
  std::optional<device::JobReportMsg> report = link_->take_report();
  const auto report_deadline = Clock::now() + milliseconds(5000);
  while (!report || report->job_id != job_.job_id) {
    if (Clock::now() > report_deadline)
      return fail(ErrorCode::kPrinter, "printer finished job " + std::to_string(job_.job_id) + " but sent no report");
    if (auto s = link_->send(device::MessageType::kReportQuery, {}); !s) return fail(from_device(s.error(), "report"));
    if (auto s = link_->poll(milliseconds(100)); !s) return fail(from_device(s.error(), "report"));
    report = link_->take_report();
  }
  active_ = false;
  ending_ = false;
  stats_.link = link_->stats();
  session_log()->info("job {} '{}' completed: {} swaths printed, {} fabric, {} cues fired", job_.job_id, job_.name,
                      report->swaths_printed, mm_text(report->feed_travel_um), report->cues_fired);
  return JobResult{*report, stats_, cues_};
}

Status PrintSession::abort_job(const std::string& reason) {
  if (!active_) return {};
  active_ = false;
  device::AbortMsg m{reason};
  if (auto s = link_->send_msg(device::MessageType::kAbort, m); !s) return fail(from_device(s.error(), "abort"));
  const auto deadline = Clock::now() + milliseconds(5000);
  while (Clock::now() < deadline) {
    if (auto s = link_->poll(milliseconds(20)); !s) return fail(from_device(s.error(), "abort"));
    const device::StatusMsg* st = link_->status();
    if (st && st->job_id != job_.job_id) return {};
  }
  return fail(ErrorCode::kPrinter, "printer did not confirm the abort of job " + std::to_string(job_.job_id));
}

}  // namespace tp::host
