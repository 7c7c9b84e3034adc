// host/bench/child_process.h: runs a measurement in a forked child so its peak memory and CPU time are
// its own.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

/// Receives one key=value figure.
using FigureSink = std::function<void(std::string_view key, std::string_view value)>;

/// What a child reported and what the kernel measured of it.
struct ChildRun {
  std::vector<std::pair<std::string, std::string>> figures;
  double peak_rss_mb = 0;  ///< ru_maxrss of the child
  double cpu_s = 0;        ///< user + system time of the child
};

/// Forks, runs `body` in the child (figures travel back through a pipe) and waits for it. Call only
/// while the process has a single thread (fork copies just the caller).
/// Fails (kIo) if the child cannot start, with the child's error if `body` fails, or when the child
/// dies on a signal.
[[nodiscard]] Result<ChildRun> run_in_child(const std::function<Status(const FigureSink&)>& body);

}  // namespace tp::rip
