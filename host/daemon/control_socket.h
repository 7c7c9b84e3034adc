// host/daemon/control_socket.h: the daemon's local control socket: one JSON object per line,
// request then reply (docs/daemon.md lists the operations).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <thread>

#include "host/common/error.h"

namespace tp::host {

/// The control-socket path for a state directory.
std::filesystem::path default_socket_path(const std::filesystem::path& state_dir);

/// Sends one request line to the daemon's socket and returns its reply line.
/// Fails with kDaemon when nothing listens there (the daemon is not running).
[[nodiscard]] Result<std::string> socket_request(const std::filesystem::path& socket_path,
                                                 const std::string& request_json, int timeout_ms = 10000);

/// Bounds on one client of the control socket.
struct ClientLimits {
  int request_timeout_ms = 2000;        ///< the whole request line must arrive within this
  std::size_t max_request_bytes = 1 << 20;
  int max_clients = 32;                 ///< served at once; more are told the daemon is busy
};

/// A listening UNIX stream socket; the daemon polls it from its main loop and each client is
/// served on its own thread, so an idle or trickling client delays nobody else.
class ControlSocket {
 public:
  ControlSocket() = default;
  ControlSocket(ControlSocket&&) noexcept;
  ControlSocket& operator=(ControlSocket&&) noexcept;
  ~ControlSocket();

  /// Binds `path` (removing a stale socket file left by a dead daemon; refusing if a live daemon
  /// answers there), mode 0660.
  [[nodiscard]] static Result<ControlSocket> listen(const std::filesystem::path& path);

  /// Waits up to `timeout_ms` for clients and starts serving each that connects on a thread of
  /// its own: read one request line (within limits.request_timeout_ms and max_request_bytes, else
  /// the client is dropped with an error line), write handler(request) back. `handler` must be
  /// callable from several threads at once and outlive the socket. Returns the clients accepted.
  int serve(int timeout_ms, const std::function<std::string(const std::string&)>& handler,
            const ClientLimits& limits = {});

  /// Clients being served now.
  int active_clients() const;

 private:
  struct Client {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  void reap(bool all);
  int fd_ = -1;
  std::filesystem::path path_;
  std::list<Client> clients_;
};

}  // namespace tp::host
