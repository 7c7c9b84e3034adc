// host/session/sim_reexec.h: commands that must talk to the simulated printer run under
// printsim. If this process is not already under printsim, re-execute it as
// `printsim run --out <dir> [--scenario f] [--printer f] [--job-dirs] -- <same argv>`, with the
// printsim that sits next to this executable.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "host/common/error.h"

namespace tp::host {

/// True when printsim started this process (it sets TP_PRINTSIM to its output folder).
bool under_printsim();
/// printsim's output folder for this process, if under printsim.
std::optional<std::filesystem::path> printsim_out_dir();

struct SimReexec {
  std::filesystem::path out_dir;                      ///< where printsim writes fabric and logs
  std::optional<std::filesystem::path> scenario;      ///< fault-injection scenario
  std::optional<std::filesystem::path> printer_model; ///< printer model file
  bool job_dirs = false;                              ///< one folder per job under out_dir
  bool fabric = true;                                 ///< false: printsim --no-fabric (benchmarks)
  double speed = 0;                                   ///< printsim --speed
};

/// Replaces this process with printsim running it (returns only on failure: kPrinter naming the
/// missing printsim or the exec error). Under printsim it does nothing and succeeds.
[[nodiscard]] Status reexec_under_printsim(int argc, char** argv, const SimReexec& options);

/// Same, with this process's own arguments (read from /proc/self/cmdline), for command handlers
/// that never see argv.
[[nodiscard]] Status reexec_under_printsim(const SimReexec& options);

/// The printsim command line reexec_under_printsim() would run (for logs and tests).
std::vector<std::string> printsim_command(int argc, char** argv, const SimReexec& options);

}  // namespace tp::host
