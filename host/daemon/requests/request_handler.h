// host/daemon/requests/request_handler.h: the control socket's operations (ping, submit, status,
// cancel) on one request line; every field of the untrusted request is checked before use.
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
