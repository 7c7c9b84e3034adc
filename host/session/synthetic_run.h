// host/session/synthetic_run.h: runs a synthetic job (synthetic_job.h) through a print session:
// a fixed number of swaths, or as many as fit in a time budget (the link benchmark).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "geometry/common/cancel.h"
#include "host/session/print_session.h"
#include "host/session/synthetic_job.h"

namespace tp::host {

struct SyntheticRunOptions {
  SyntheticJob job;
  std::uint64_t job_id = 1;
  std::string name = "synthetic";
  std::uint32_t first_swath = 0;  ///< resume from here (earlier swaths are handed in and skipped)
  double seconds = 0;             ///< >0: stream swaths for this long instead of job.swaths
};

struct SyntheticRunResult {
  JobResult job;
  std::uint32_t swaths = 0;       ///< swaths in the job
  std::uint64_t data_bytes = 0;   ///< swath data handed to the session
  double stream_s = 0;            ///< first swath handed in -> job ended
  double throughput_MBps = 0;     ///< data_bytes / stream_s, in 10^6 bytes per second
  std::vector<SyntheticCue> cues; ///< as queued, in order of cue id
};

/// Opens the job, queues its cues, hands in its swaths and ends it. Errors are the session's.
[[nodiscard]] Result<SyntheticRunResult> run_synthetic_job(PrintSession& session, const SyntheticRunOptions& options,
                                                           const geometry::CancelToken& cancel);

}  // namespace tp::host
