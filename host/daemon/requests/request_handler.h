// host/daemon/requests/request_handler.h: the daemon's operations (ping, submit, status, cancel,
// reprint, events) on one JSON request, for the control socket and the HTTP API; every field is checked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "host/common/error.h"
#include "host/store/job_store.h"

namespace tp::host {

/// What the handler asks of the daemon around the store.
struct RequestHooks {
  /// Validates and queues a package (an absolute path); `reprint` queues it even when the same
  /// content is already queued, running or done. Returns the reply's fields ({"id", "name", ...}).
  std::function<Result<nlohmann::json>(const std::filesystem::path& package, bool reprint)> submit;
  /// A running job was asked to cancel: stop it now if this process runs it.
  std::function<void(std::int64_t id)> cancel_running;
  /// Queues job `id`'s package again (kept by content hash in the state directory), even though
  /// the same content printed before. Returns the new job's fields ({"id", "name", ...}).
  std::function<Result<nlohmann::json>(std::int64_t id)> reprint;
  /// Events after sequence number `after` (job `job` only when non-zero), waiting up to `wait_ms`
  /// for one: {"events": [...], "last": newest seq, "gap": older ones were dropped}.
  std::function<nlohmann::json(std::uint64_t after, std::int64_t job, int wait_ms)> events;
  /// A queued job was cancelled: release its spooled package.
  std::function<void(std::int64_t id)> cancelled_queued;
};

/// Most jobs `status` lists without an "id".
inline constexpr int kMaxStatusLimit = 1000;

/// Handles one request line and returns the reply line (valid UTF-8 JSON, no newline). Never
/// throws: a malformed request gets {"ok":false,"error":"..."} naming the field.
std::string handle_request(JobStore& store, const std::string& request_line, const RequestHooks& hooks) noexcept;

/// A job record as the socket shows it (text that is not UTF-8 is shown with \xNN escapes).
nlohmann::json job_record_json(const JobRecord& r);

}  // namespace tp::host
