// host/daemon/events/event_log.cpp: the bounded, sequence-numbered event log and its SSE framing.
#include "host/daemon/events/event_log.h"

#include "host/common/text.h"

namespace tp::host {

namespace {
std::int64_t unix_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}
}  // namespace

EventLog::EventLog(std::size_t capacity, std::uint64_t first_seq)
    : capacity_(capacity == 0 ? 1 : capacity),
      next_seq_(first_seq != 0 ? first_seq
                               : static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                                                std::chrono::system_clock::now().time_since_epoch())
                                                                .count())) {}

std::uint64_t EventLog::publish(std::string type, std::int64_t job_id, nlohmann::json data) {
  std::uint64_t seq;
  {
    std::lock_guard lock(mu_);
    seq = next_seq_++;
    events_.push_back(DaemonEvent{seq, std::move(type), job_id, unix_ms(), std::move(data)});
    while (events_.size() > capacity_) events_.pop_front();
  }
  cv_.notify_all();
  return seq;
}

EventBatch EventLog::read_after(std::uint64_t after, std::size_t max, std::chrono::milliseconds wait) {
  std::unique_lock lock(mu_);
  if (after >= next_seq_) after = 0;
  // Sequence numbers are dense, so whether `after` is still covered is one comparison.
  cv_.wait_for(lock, wait, [&] { return closed_ || (!events_.empty() && events_.back().seq > after); });
  EventBatch out;
  out.first_kept = events_.empty() ? 0 : events_.front().seq;
  out.gap = !events_.empty() && events_.front().seq > after + 1;
  for (const auto& e : events_) {
    if (e.seq <= after) continue;
    if (out.events.size() >= max) break;
    out.events.push_back(e);
  }
  return out;
}

std::uint64_t EventLog::last_seq() const {
  std::lock_guard lock(mu_);
  return next_seq_ - 1;
}

void EventLog::close() {
  {
    std::lock_guard lock(mu_);
    closed_ = true;
  }
  cv_.notify_all();
}

std::string to_sse(const DaemonEvent& e) {
  nlohmann::json j = e.data.is_object() ? e.data : nlohmann::json::object();
  j["seq"] = e.seq;
  j["type"] = e.type;
  j["job_id"] = e.job_id;
  j["time_ms"] = e.time_ms;
  return "id: " + std::to_string(e.seq) + "\nevent: " + e.type + "\ndata: " + dump_json(j) + "\n\n";
}

}  // namespace tp::host
