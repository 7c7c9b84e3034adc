// host/daemon/daemon.h: printd: hot folder, control socket, persistent queue and one print worker.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "host/common/error.h"
#include "host/daemon/control_socket.h"
#include "host/daemon/http/http_server.h"
#include "host/job/package.h"
#include "host/job/printer_choice.h"

namespace tp::host {

struct DaemonConfig {
  std::filesystem::path state_dir;     ///< jobs.db, spool/, printd.sock live here (made 0700)
  std::filesystem::path hot_folder;    ///< empty = no hot folder
  std::filesystem::path out_dir;       ///< job outputs: <out_dir>/<job-name>/
  std::filesystem::path socket_path;   ///< default <state_dir>/printd.sock
  std::optional<PrinterChoice> printer_override;  ///< none = each job's own; kNone = never print
  int hot_folder_poll_ms = 500;
  int hot_folder_settle_ms = 2000;     ///< an entry must hold still this long before it is taken
  ClientLimits clients;                ///< control-socket clients: timeout, size, how many at once
  PackageLimits limits;                ///< what a job may hold and ask for (docs/daemon.md)
  int max_crashes = 1;                 ///< fatal signals while running a job before it is failed
  int max_unclean_exits = 8;           ///< kill -9 / power losses while running a job before it is failed
  HttpConfig http;                     ///< the HTTP API (docs/daemon.md, docs/api.yaml)
  std::size_t event_log_size = 4096;   ///< events kept for Last-Event-ID replay
};

/// Runs the daemon until `stop` becomes true (SIGTERM/SIGINT in printd). A job running at stop
/// is interrupted and resumes from its print checkpoint at the next start.
[[nodiscard]] Status run_daemon(const DaemonConfig& config, const std::atomic<bool>& stop);

}  // namespace tp::host
