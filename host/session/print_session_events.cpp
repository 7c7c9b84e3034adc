// host/session/print_session_events.cpp: what the print session does between swaths: reading
// printer status (acks, credits, pauses, faults), firing cues on the cutting table, watching the
// emergency stop, and reconnecting after an unplug.
#include <algorithm>
#include <cstdio>
#include <thread>

#include "host/session/internal/session_log.h"
#include "host/session/print_session.h"

namespace tp::host {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {
// How often the emergency-stop input is read while the session waits or streams.
constexpr milliseconds kEstopPeriod{10};
constexpr milliseconds kCutterPoll{5};
}  // namespace

Status PrintSession::check_emergency_stop() {
  if (!gpio_ || !active_) return {};
  const auto now = Clock::now();
  if (now - last_estop_check_ < kEstopPeriod) return {};
  last_estop_check_ = now;
  auto pressed = gpio_->emergency_stop();
  if (!pressed) return fail_job(ErrorCode::kPrinter, "reading the emergency stop: " + pressed.error().message);
  if (*pressed)
    return fail_job(ErrorCode::kPrinter, "emergency stop pressed (input '" + gpio_->config().emergency_stop + "')");
  return {};
}

Status PrintSession::service(milliseconds wait, const geometry::CancelToken* cancel) {
  if (cancel && cancel->cancelled() && active_) {
    (void)abort_job("cancelled by the operator");
    return fail(ErrorCode::kCancelled, "job " + std::to_string(job_.job_id) + " cancelled" + job_where());
  }
  if (auto s = check_emergency_stop(); !s) return s;
  if (auto s = link_->poll(wait); !s) {
    if (s.error().code == device::ErrorCode::kDisconnected) return recover(s.error());
    return fail_job(ErrorCode::kPrinter, "printer link: " + s.error().message);
  }
  return absorb_status();
}

Status PrintSession::absorb_status() {
  if (auto r = link_->take_reject()) {
    // Frames sent before the printer lost the job are refused for want of a job: not an error,
    // the resume below (or already done) sends them again.
    const device::StatusMsg* now = link_->status();
    const bool lost_now = now && now->job_id != job_.job_id && now->last_job_id == job_.job_id &&
                          now->last_outcome == device::JobOutcome::kLost;
    // A job_end the printer refuses because it already completed the job (re-attached as it finished).
    const bool completed_now = now && now->job_id != job_.job_id && now->last_job_id == job_.job_id &&
                               now->last_outcome == device::JobOutcome::kCompleted && ending_;
    if (active_ && r->code == device::ErrorCode::kBadState && (lost_now || completed_now || r->seq < reopen_seq_)) {
      session_log()->info("printer refused {} sent before it lost the job: {}", device::to_string(r->refused), r->message);
    } else if (active_)
      return fail_job(ErrorCode::kPrinter, "printer refused " + std::string(device::to_string(r->refused)) + ": " +
                                               r->message);
    session_log()->warn("printer refused {}: {}", device::to_string(r->refused), r->message);
  }
  const device::StatusMsg* st = link_->status();
  if (!st || link_->status_serial() == seen_status_) return {};
  seen_status_ = link_->status_serial();
  const device::StatusMsg s = *st;
  if (on_status_) on_status_(s);
  if (paused_since_ && s.state != device::PrinterState::kPaused) {
    stats_.pause_s += std::chrono::duration<double>(Clock::now() - *paused_since_).count();
    paused_since_.reset();
    session_log()->info("printer resumed");
  }
  if (!active_) return {};
  // The printer dropped the job (buffer cleared, or power lost while we were connected).
  if (s.job_id != job_.job_id && s.last_job_id == job_.job_id && s.last_outcome == device::JobOutcome::kLost) {
    bool disconnected = false;
    auto r = resume_lost_job(s, disconnected);
    if (!r && disconnected) return recover(device::Error{device::ErrorCode::kDisconnected, r.error().message});
    return r;
  }
  if (s.job_id != job_.job_id) return {};
  // Checkpoints: every swath the printer has committed, in order, then every one it printed.
  while (acked_next_ < s.swath_next) {
    ++stats_.swaths_acked;
    if (on_acked_) on_acked_(acked_next_);
    ++acked_next_;
  }
  note_printed(s);

  if (s.state == device::PrinterState::kFault)
    return fail_job(ErrorCode::kPrinter, "printer fault: " + std::string(device::describe(s.condition)));
  if (s.state == device::PrinterState::kPaused) {
    if (!paused_since_) {
      paused_since_ = Clock::now();
      session_log()->warn("printer paused: {}", device::describe(s.condition));
    } else if (Clock::now() - *paused_since_ > config_.max_pause) {
      return fail_job(ErrorCode::kPrinter, "printer paused longer than " + std::to_string(config_.max_pause.count()) +
                                               " ms: " + std::string(device::describe(s.condition)));
    }
  }
  if (s.cue_waiting != 0) return fire_cue(s.cue_waiting, nullptr);
  return {};
}

Status PrintSession::fire_cue(std::uint32_t id, const geometry::CancelToken* cancel) {
  auto it = std::find_if(cues_.begin(), cues_.end(), [&](const CueRecord& c) { return c.id == id; });
  if (it == cues_.end()) {
    // A printer re-attached after a host restart may stand at a cue this session has not queued
    // yet: queue_cue() fires it once it is known.
    if (id > cues_.size()) return {};
    return fail_job(ErrorCode::kPrinter, "printer stopped at unknown cue " + std::to_string(id));
  }
  CueRecord& cue = *it;
  char pos[64];
  std::snprintf(pos, sizeof pos, "%s at %.1f mm", std::string(device::to_string(cue.kind)).c_str(),
                static_cast<double>(cue.position_um) / 1000.0);
  if (gpio_ && !cue.fired) {
    // The printer holds the fabric still; the cutter must be ready before we cue it.
    const auto deadline = Clock::now() + config_.cutter_ready_timeout;
    for (;;) {
      auto ready = gpio_->cutter_ready();
      if (!ready) return fail_job(ErrorCode::kPrinter, "reading cutter-ready: " + ready.error().message);
      if (*ready) break;
      if (Clock::now() > deadline)
        return fail_job(ErrorCode::kPrinter, "cutter not ready for cue " + std::to_string(id) + " (" + pos +
                                                 "): waited " + std::to_string(config_.cutter_ready_timeout.count()) +
                                                 " ms on input '" + gpio_->config().cutter_ready + "'");
      if (cancel && cancel->cancelled()) return fail(ErrorCode::kCancelled, "cancelled while waiting for the cutter");
      if (auto s = check_emergency_stop(); !s) return s;
      std::this_thread::sleep_for(kCutterPoll);
    }
    const auto line = cue.kind == device::CueKind::kCut ? drivers::GpioOutput::kCutterCue : drivers::GpioOutput::kNotchMark;
    if (auto p = gpio_->pulse(line, config_.cue_pulse); !p)
      return fail_job(ErrorCode::kPrinter, "firing cue " + std::to_string(id) + ": " + p.error().message);
  }
  if (!cue.fired) {
    cue.fired = true;
    const device::StatusMsg* s = link_->status();
    cue.fired_at_um = s ? s->fabric_pos_um : 0;
    if (on_cue_fired_) on_cue_fired_(cue);
  }
  device::CueDoneMsg done{id};
  if (auto s = link_->send_msg(device::MessageType::kCueDone, done); !s) {
    if (s.error().code == device::ErrorCode::kDisconnected) return recover(s.error());
    return fail_job(ErrorCode::kPrinter, "cue " + std::to_string(id) + ": " + s.error().message);
  }
  return {};
}

Status PrintSession::recover(const device::Error& cause) {
  const auto t0 = Clock::now();
  session_log()->warn("printer link lost ({}); reconnecting", cause.message);
  for (int attempt = 1;; ++attempt) {
    if (auto r = transport_->reconnect(config_.reconnect_timeout); !r) {
      active_ = false;
      return fail(ErrorCode::kPrinter, "printer unplugged and not back: " + r.error().message + job_where());
    }
    auto id = link_->handshake();
    if (!id) {
      if (id.error().code == device::ErrorCode::kDisconnected && attempt < 3) continue;
      active_ = false;
      return fail(ErrorCode::kPrinter, "printer back but handshake failed: " + id.error().message + job_where());
    }
    identity_ = *id;
    if (!active_) break;
    // Ask the printer what it holds of the job, then re-attach or resume what it lost.
    auto q = link_->query_status(milliseconds(5000));
    if (!q) {
      if (q.error().code == device::ErrorCode::kDisconnected && attempt < 3) continue;
      return fail_job(ErrorCode::kPrinter, "asking the printer after reconnect: " + q.error().message);
    }
    const device::StatusMsg st = *q;
    bool again = false;
    if (st.job_id != job_.job_id) {
      if (st.last_job_id == job_.job_id && st.last_outcome == device::JobOutcome::kCompleted && ending_) break;
      if (st.last_job_id == job_.job_id && st.last_outcome == device::JobOutcome::kLost) {
        bool disconnected = false;
        auto r = resume_lost_job(st, disconnected);
        if (r) break;
        if (!disconnected || attempt >= 3) return active_ ? fail_job(r.error().code, r.error().message) : r;
        continue;
      }
      return fail_job(ErrorCode::kPrinter, "printer lost the job while unplugged and keeps no record of it (it reports " +
                                               (st.job_id ? "job " + std::to_string(st.job_id) : std::string("no job")) +
                                               "): check the fabric, cut off the partial print and print the job again");
    }
    device::JobBeginMsg m{job_.job_id, job_.name, acked_next_, job_.fabric_width_px, st.fabric_pos_um};
    if (auto sent = link_->send_msg(device::MessageType::kJobBegin, m); !sent) {
      if (sent.error().code == device::ErrorCode::kDisconnected && attempt < 3) continue;
      return fail_job(ErrorCode::kPrinter, "re-attaching after reconnect: " + sent.error().message);
    }
    seen_status_ = 0;
    if (auto a = absorb_status(); !a) return a;
    if (auto r = resend_after_reconnect(st, again); !r) return r;
    if (!again) break;
    if (attempt >= 3) return fail_job(ErrorCode::kPrinter, "printer kept disconnecting during recovery");
  }
  ++stats_.reconnects;
  stats_.recovery_ms_last = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  stats_.recovery_ms_max = std::max(stats_.recovery_ms_max, stats_.recovery_ms_last);
  session_log()->info("printer back after {:.0f} ms; resuming job {} at swath {}", stats_.recovery_ms_last, job_.job_id,
                      acked_next_);
  return {};
}

}  // namespace tp::host
