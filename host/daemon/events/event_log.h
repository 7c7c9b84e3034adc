// host/daemon/events/event_log.h: printd's bounded log of job, stage-progress and printer events,
// each with a monotonic sequence number, so a client reconnecting with Last-Event-ID misses nothing.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tp::host {

/// One event: `type` is "job" (state change), "progress" (stage and fraction) or "printer".
struct DaemonEvent {
  std::uint64_t seq = 0;     ///< dense and increasing; starts at the start time in µs, so a restart never reuses one
  std::string type;
  std::int64_t job_id = 0;   ///< 0 for printer events
  std::int64_t time_ms = 0;  ///< Unix time, ms
  nlohmann::json data;       ///< the event's fields (state, stage, fraction, swath...)
};

/// What a reader gets back: the events after its sequence number, and whether older ones it
/// asked for had already been dropped from the bounded log (`gap`).
struct EventBatch {
  std::vector<DaemonEvent> events;
  bool gap = false;
  std::uint64_t first_kept = 0;  ///< oldest sequence number still in the log (0 when empty)
};

/// Thread-safe: the print worker publishes, any number of HTTP clients read.
class EventLog {
 public:
  /// Keeps the newest `capacity` events (at least 1). The first event's number is `first_seq`;
  /// by default the current Unix time in microseconds, so numbers keep growing across restarts
  /// and a client's Last-Event-ID from an earlier run reads as a gap, not as the future.
  explicit EventLog(std::size_t capacity = 4096, std::uint64_t first_seq = 0);

  /// Appends an event and wakes readers; returns its sequence number.
  std::uint64_t publish(std::string type, std::int64_t job_id, nlohmann::json data);

  /// Events with seq > `after` (at most `max`), waiting up to `wait` for one if there are none yet.
  /// An `after` beyond the newest event (another run's number) is read as "from the start".
  [[nodiscard]] EventBatch read_after(std::uint64_t after, std::size_t max, std::chrono::milliseconds wait);

  /// Sequence number of the newest event (0 before the first).
  [[nodiscard]] std::uint64_t last_seq() const;

  /// Wakes every waiting reader at once (the server is stopping).
  void close();

 private:
  const std::size_t capacity_;
  mutable std::mutex mu_;
  std::condition_variable cv_;
  std::deque<DaemonEvent> events_;
  std::uint64_t next_seq_;
  bool closed_ = false;
};

/// The event as one Server-Sent Events frame: `id:`, `event:` and one `data:` line of JSON
/// ({"seq","type","job_id","time_ms",...data}), ended by a blank line.
std::string to_sse(const DaemonEvent& e);

}  // namespace tp::host
