// host/daemon/daemon.h: printd: hot folder, control socket, persistent queue and one print worker.
#pragma once

#include <atomic>
#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

struct DaemonConfig {
  std::filesystem::path state_dir;     ///< jobs.db, spool/, printd.sock live here
  std::filesystem::path hot_folder;    ///< empty = no hot folder
  std::filesystem::path out_dir;       ///< job outputs: <out_dir>/<job-name>/
  std::filesystem::path socket_path;   ///< default <state_dir>/printd.sock
  std::string printer_override;        ///< "" = each job's own; "none" = never print
  int hot_folder_poll_ms = 500;
};

/// Runs the daemon until `stop` becomes true (SIGTERM/SIGINT in printd). A job running at stop
/// is interrupted and resumes from its print checkpoint at the next start.
[[nodiscard]] Status run_daemon(const DaemonConfig& config, const std::atomic<bool>& stop);

}  // namespace tp::host
