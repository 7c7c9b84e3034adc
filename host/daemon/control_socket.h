// host/daemon/control_socket.h: the daemon's local control socket: one JSON object per line,
// request then reply (docs/daemon.md lists the operations).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// The control-socket path for a state directory.
std::filesystem::path default_socket_path(const std::filesystem::path& state_dir);

/// Sends one request line to the daemon's socket and returns its reply line.
/// Fails with kDaemon when nothing listens there (the daemon is not running).
[[nodiscard]] Result<std::string> socket_request(const std::filesystem::path& socket_path,
                                                 const std::string& request_json, int timeout_ms = 10000);

/// A listening UNIX stream socket; the daemon polls it from its main loop.
class ControlSocket {
 public:
  ControlSocket() = default;
  ControlSocket(ControlSocket&&) noexcept;
  ControlSocket& operator=(ControlSocket&&) noexcept;
  ~ControlSocket();

  /// Binds `path` (removing a stale socket file left by a dead daemon; refusing if a live daemon
  /// answers there), mode 0660.
  [[nodiscard]] static Result<ControlSocket> listen(const std::filesystem::path& path);

  /// Waits up to `timeout_ms` for one client; if one connects, reads its request line and
  /// writes handler(request) back. Returns true if a request was served.
  bool serve_one(int timeout_ms, const std::function<std::string(const std::string&)>& handler);

 private:
  int fd_ = -1;
  std::filesystem::path path_;
};

}  // namespace tp::host
