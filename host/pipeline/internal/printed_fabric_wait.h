// host/pipeline/internal/printed_fabric_wait.h: waiting, woken by the file system, for printsim
// to write a job's printed fabric image, with a timeout that fails naming the folder and job.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "geometry/common/cancel.h"
#include "host/common/error.h"

namespace tp::host::internal {

/// How long a job waits, after its print ended, for printsim's fabric images. printsim writes them
/// on its writer thread once the job has ended (measured 1 to 6 s on the demo jobs, 2 cores
/// shared); two minutes covers a long roll behind another job's images in that queue.
inline constexpr double kPrintedFabricTimeout_s = 120;

struct PrintedFabricWait {
  std::filesystem::path printsim_dir;  ///< printsim's --out folder (TP_PRINTSIM)
  std::int64_t job_id = 0;
  /// A printer.json last written before this is an earlier run's (a job id reused by a fresh
  /// printd state folder, or printctl run into the same printsim folder) and is not waited on.
  std::optional<std::filesystem::file_time_type> not_before;
  double timeout_s = kPrintedFabricTimeout_s;
};

/// What printsim recorded for the job: its fabric-lab.tif, or why there is none.
struct PrintedFabric {
  std::optional<std::filesystem::path> fabric_lab;
  std::string reason;  ///< set when printsim recorded the job without a colorimetric fabric
};

/// Waits for printsim's printer.json naming `job_id` in `printsim_dir` or in one of its
/// `<job id>-<name>` folders (printsim --job-dirs), then returns the fabric-lab.tif beside it, or
/// a reason when printsim recorded the job without one (--no-fabric). The wait sleeps on inotify
/// events of those folders (a folder created meanwhile is watched too) and looks again at least
/// every second, so a file system without inotify still works. Fails with kPrinter naming the
/// folder, the job and the timeout when nothing comes in `timeout_s`, kIo when the folder does not
/// exist, kCancelled when `cancel` is set.
[[nodiscard]] Result<PrintedFabric> wait_for_printed_fabric(const PrintedFabricWait& wait,
                                                            const geometry::CancelToken& cancel);

}  // namespace tp::host::internal
