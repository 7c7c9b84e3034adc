// host/common/failure_report.h: a job's report.json is always left behind, even when the job
// failed before the pipeline started or the disk filled up while it ran.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// Size of the placeholder report.json written before a job runs. Rewriting a report of at most
/// this size in place reuses the placeholder's disk blocks, so it succeeds on a full disk.
inline constexpr std::size_t kReservedReportBytes = 4096;

/// Writes `<out_dir>/report.json` saying the job is running, padded to kReservedReportBytes
/// (creating out_dir). Fails (kIo) naming the path.
[[nodiscard]] Status reserve_report(const std::filesystem::path& out_dir, const std::string& job_name,
                                    std::int64_t job_id);

/// Makes sure `<out_dir>/report.json` records that the job ended in `state` ("failed",
/// "cancelled") with `error`: leaves a complete report that already says so (the pipeline's own),
/// else overwrites the file in place with a short one (within kReservedReportBytes).
[[nodiscard]] Status ensure_failure_report(const std::filesystem::path& out_dir, const std::string& job_name,
                                           std::int64_t job_id, const std::string& state, const std::string& error);

}  // namespace tp::host
