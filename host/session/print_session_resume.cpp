// host/session/print_session_resume.cpp: where a job resumes: asking the printer which job and
// swath it holds, re-attaching to a job it kept, resuming one it lost from its last printed swath
// with the fabric position continuous, and resending what it had not printed.
#include <algorithm>
#include <cstdio>

#include "host/session/internal/session_log.h"
#include "host/session/internal/session_text.h"
#include "host/session/print_session.h"

namespace tp::host {

using std::chrono::milliseconds;

using internal::from_device;
using internal::mm_text;

void PrintSession::note_printed(const device::StatusMsg& st) {
  if (st.printed_next <= printed_next_) return;
  printed_next_ = st.printed_next;
  while (!unprinted_.empty() && unprinted_.front().header.index < printed_next_) unprinted_.pop_front();
  if (on_printed_) on_printed_(printed_next_ - 1, st.printed_fabric_um);
}

Status PrintSession::attach_or_open(const device::StatusMsg& st) {
  const std::uint64_t id = job_.job_id;
  const std::string job = "job " + std::to_string(id) + " '" + job_.name + "'";
  if (st.job_id == id) {
    // Still open from an earlier session (the host restarted): the printer keeps its buffer and
    // prints it; the host goes on after the last swath the printer received.
    device::JobBeginMsg m{id, job_.name, st.swath_next, job_.fabric_width_px, st.fabric_pos_um};
    if (auto s = link_->send_msg(device::MessageType::kJobBegin, m); !s) return fail(from_device(s.error(), "job_begin"));
    auto now = link_->query_status(milliseconds(5000));
    if (!now) return fail(from_device(now.error(), "job_begin"));
    if (auto r = link_->take_reject()) return fail(ErrorCode::kPrinter, "printer refused to re-attach " + job + ": " + r->message);
    if (now->job_id != id) return fail(ErrorCode::kPrinter, "printer dropped " + job + " while re-attaching");
    active_ = true;
    stats_.reattached = true;
    acked_next_ = next_send_ = swath_count_ = now->swath_next;
    printed_next_ = now->printed_next;
    reattach_held_until_ = now->swath_next;
    reattach_held_bytes_ =
        identity_.swath_buffer_bytes - std::min<std::size_t>(now->free_bytes, identity_.swath_buffer_bytes);
    planned_end_um_ = now->queued_fabric_um;
    session_log()->info("{} still open on the printer: swaths below {} printed (fabric at {}), below {} received; "
                        "resuming at swath {}",
                        job, now->printed_next, mm_text(now->fabric_pos_um), now->swath_next, next_send_);
    seen_status_ = 0;
    return absorb_status();
  }
  if (st.job_id == 0 && st.last_job_id == id) {
    if (st.last_outcome == device::JobOutcome::kCompleted) {
      // The printer finished the job while the host was away: nothing is printed again.
      active_ = true;
      finished_on_printer_ = true;
      acked_next_ = printed_next_ = next_send_ = swath_count_ = st.last_printed_next;
      planned_end_um_ = st.last_fabric_pos_um;
      session_log()->info("{} was completed by the printer ({} swaths); not printing it again", job, st.last_printed_next);
      return {};
    }
    if (st.last_outcome == device::JobOutcome::kLost) {
      bool disconnected = false;
      return resume_lost_job(st, disconnected);
    }
  }
  if (job_.first_swath > 0) {
    const std::string holds = st.job_id != 0 ? "holds job " + std::to_string(st.job_id)
                                             : st.last_job_id == id ? "ended it as " + std::string(device::to_string(st.last_outcome))
                                                                    : "has no record of it";
    return fail(ErrorCode::kPrinter, job + " was printed up to swath " + std::to_string(job_.first_swath - 1) +
                                         " but the printer " + holds +
                                         ": check the fabric, cut off the partial print and print the job again");
  }
  return open_on_printer(0, 0);
}

Status PrintSession::open_on_printer(std::uint32_t first_swath, std::int64_t fabric_pos_um) {
  const JobStart& job = job_;
  device::JobBeginMsg m{job.job_id, job.name, first_swath, job.fabric_width_px, fabric_pos_um};
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (auto s = link_->send_msg(device::MessageType::kJobBegin, m); !s) return fail(from_device(s.error(), "job_begin"));
    auto st = link_->query_status(milliseconds(5000));
    if (!st) return fail(from_device(st.error(), "job_begin"));
    if (auto r = link_->take_reject()) {
      if (attempt == 0 && r->refused == device::MessageType::kJobBegin && st->job_id != 0) {
        // A job left open by an earlier session that died: this host owns the printer.
        session_log()->warn("printer holds job {} from an earlier session; aborting it", st->job_id);
        device::AbortMsg abort{"stale job from an earlier session"};
        if (auto s = link_->send_msg(device::MessageType::kAbort, abort); !s) return fail(from_device(s.error(), "abort"));
        continue;
      }
      return fail(ErrorCode::kPrinter, "printer refused job " + std::to_string(job.job_id) + ": " + r->message);
    }
    if (st->job_id != job.job_id)
      return fail(ErrorCode::kPrinter, "printer did not open job " + std::to_string(job.job_id));
    active_ = true;
    seen_status_ = 0;
    if (auto a = absorb_status(); !a) return a;
    session_log()->info("job {} '{}' open on the printer from swath {}", job.job_id, job.name, first_swath);
    return {};
  }
  return fail(ErrorCode::kPrinter, "printer refused job " + std::to_string(job.job_id));
}

Status PrintSession::resume_lost_job(const device::StatusMsg& st, bool& disconnected) {
  disconnected = false;
  const std::uint32_t k = st.last_printed_next;
  const std::int64_t laid_um = st.last_printed_fabric_um, stands_um = st.last_fabric_pos_um;
  const std::string job = "job " + std::to_string(job_.job_id) + " '" + job_.name + "'";
  session_log()->warn("printer lost {} (power loss or buffer cleared): swaths below {} are on the fabric, the last laid "
                      "at {}, fabric at {}; resuming from swath {}",
                      job, k, mm_text(laid_um), mm_text(stands_um), k);
  auto stop = [&](const std::string& why) -> Status {
    const std::string msg = "printer lost " + job + " after printing swaths below " + std::to_string(k) + ": " + why;
    if (active_) return fail_job(ErrorCode::kPrinter, msg);
    return fail(ErrorCode::kPrinter, msg);
  };
  const bool in_session = active_;
  if (in_session) {
    // What we still hold must start at the first swath the printer did not print.
    while (!unprinted_.empty() && unprinted_.front().header.index < k) unprinted_.pop_front();
    const std::uint32_t held_from = unprinted_.empty() ? next_send_ : unprinted_.front().header.index;
    if (k > next_send_) return stop("it reports more swaths printed than were sent (" + std::to_string(next_send_) + ")");
    if (held_from != k)
      return stop("swaths " + std::to_string(k) + ".." + std::to_string(held_from - 1) +
                  " are no longer held by the host; cut off the partial print and print the job again");
  } else {
    // A new session: the pipeline hands in the swaths from k; their feeds start where k-1 was laid.
    next_send_ = swath_count_ = k;
    planned_end_um_ = laid_um;
  }
  // The planned feed of swath k starts where swath k-1 was laid; the fabric stands at stands_um.
  feed_fix_swath_ = k;
  feed_fix_um_ = laid_um - stands_um;
  lost_at_um_ = stands_um;
  active_ = false;  // the printer has no job open until the job_begin below
  device::JobBeginMsg m{job_.job_id, job_.name, k, job_.fabric_width_px, stands_um};
  reopen_seq_ = link_->next_seq();
  auto sent = link_->send_msg(device::MessageType::kJobBegin, m);
  std::optional<device::StatusMsg> now;
  device::Error e;
  if (!sent) {
    e = sent.error();
  } else if (auto q = link_->query_status(milliseconds(5000)); !q) {
    e = q.error();
  } else {
    now = *q;
  }
  if (!now) {
    disconnected = e.code == device::ErrorCode::kDisconnected;
    active_ = in_session;
    if (disconnected) return fail(ErrorCode::kPrinter, "reopening " + job + ": " + e.message);
    return stop("reopening it: " + e.message);
  }
  if (auto r = link_->take_reject(); r && r->seq >= reopen_seq_) {
    active_ = in_session;
    return stop("it refused to reopen it: " + r->message);
  }
  if (now->job_id != job_.job_id || now->swath_next != k) {
    active_ = in_session;
    return stop("it did not reopen it at swath " + std::to_string(k));
  }
  active_ = true;
  acked_next_ = printed_next_ = k;
  ++stats_.lost_job_resumes;
  // Cues not yet fired go back to the printer (one it stood at fires at once); swaths from k.
  for (const auto& c : cues_) {
    if (c.fired || c.id > cues_sent_) continue;
    device::CutterCueMsg cm{c.id, c.kind, c.position_um, c.x_um};
    if (auto s = link_->send_msg(device::MessageType::kCutterCue, cm); !s) {
      disconnected = s.error().code == device::ErrorCode::kDisconnected;
      return disconnected ? fail(ErrorCode::kPrinter, s.error().message) : stop("re-registering cues: " + s.error().message);
    }
  }
  for (const auto& sw : unprinted_) {
    if (auto s = send_wire_swath(sw); !s) {
      disconnected = s.error().code == device::ErrorCode::kDisconnected;
      return disconnected ? fail(ErrorCode::kPrinter, s.error().message) : stop(s.error().message);
    }
    ++stats_.swaths_resent;
  }
  if (ending_) {
    device::JobEndMsg end{swath_count_, final_feed_um_};
    if (auto s = link_->send_msg(device::MessageType::kJobEnd, end); !s) {
      disconnected = s.error().code == device::ErrorCode::kDisconnected;
      return disconnected ? fail(ErrorCode::kPrinter, s.error().message) : stop("resending job end: " + s.error().message);
    }
  }
  seen_status_ = 0;
  session_log()->info("{} reopened on the printer at swath {} with the fabric at {}", job, k, mm_text(stands_um));
  return {};
}

Status PrintSession::resend_after_reconnect(const device::StatusMsg& st, bool& again) {
  again = false;
  // Cues the printer never registered, then every swath it has not acknowledged.
  for (const auto& c : cues_) {
    if (c.id <= st.cues_registered || c.id > cues_sent_ || c.fired) continue;
    device::CutterCueMsg cm{c.id, c.kind, c.position_um, c.x_um};
    if (auto s = link_->send_msg(device::MessageType::kCutterCue, cm); !s) {
      again = s.error().code == device::ErrorCode::kDisconnected;
      if (!again) return fail_job(ErrorCode::kPrinter, "re-registering cue: " + s.error().message);
      return {};
    }
  }
  for (const auto& sw : unprinted_) {
    if (sw.header.index < st.swath_next) continue;
    if (auto s = send_wire_swath(sw); !s) {
      again = s.error().code == device::ErrorCode::kDisconnected;
      if (!again) return fail_job(ErrorCode::kPrinter, "resending swath: " + s.error().message);
      return {};
    }
    ++stats_.swaths_resent;
  }
  if (ending_) {
    device::JobEndMsg end{swath_count_, final_feed_um_};
    if (auto s = link_->send_msg(device::MessageType::kJobEnd, end); !s) {
      again = s.error().code == device::ErrorCode::kDisconnected;
      if (!again) return fail_job(ErrorCode::kPrinter, "resending job end: " + s.error().message);
    }
  }
  return {};
}

}  // namespace tp::host
