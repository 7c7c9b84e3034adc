// host/session/synthetic_run.cpp: driving a synthetic job through a print session.
#include "host/session/synthetic_run.h"

#include <chrono>

namespace tp::host {

Result<SyntheticRunResult> run_synthetic_job(PrintSession& session, const SyntheticRunOptions& o,
                                             const geometry::CancelToken& cancel) {
  using Clock = std::chrono::steady_clock;
  const device::IdentifyMsg& printer = session.printer();
  SyntheticRunResult out;
  JobStart start{o.job_id, o.name, o.first_swath, 0};
  start.fabric_width_px = static_cast<std::uint32_t>(o.job.x_start_px + o.job.width_px + o.job.x_start_px);
  if (auto s = session.begin_job(start); !s) return fail(s.error());
  SyntheticJob job = o.job;
  if (o.seconds <= 0) {
    out.cues = synthetic_cues(job, printer);
    for (const auto& c : out.cues)
      if (auto s = session.queue_cue(c.kind, c.position_um, c.x_um); !s) return fail(s.error());
  }
  // A timed run recycles a few pre-built payloads: generating data must not be what is measured.
  std::vector<device::Swath> pool;
  if (o.seconds > 0)
    for (std::uint32_t i = 0; i < 4; ++i) pool.push_back(make_synthetic_swath(job, printer, i));
  const auto t0 = Clock::now();
  std::uint32_t index = 0;
  for (;; ++index) {
    if (o.seconds > 0 ? std::chrono::duration<double>(Clock::now() - t0).count() >= o.seconds : index >= job.swaths)
      break;
    device::Swath swath;
    if (o.seconds > 0) {
      swath = pool[index % pool.size()];
      swath.header.index = index;
      swath.header.first_row = static_cast<std::int64_t>(index) * swath.header.rows;
      swath.header.feed_before_um =
          index == 0 ? 0
                     : static_cast<std::uint32_t>(synthetic_position_um(job, printer, index) -
                                                  synthetic_position_um(job, printer, index - 1));
    } else {
      swath = make_synthetic_swath(job, printer, index);
    }
    out.data_bytes += swath.data.size();
    if (auto s = session.send_swath(swath, cancel); !s) return fail(s.error());
  }
  out.swaths = index;
  job.swaths = index;
  const std::uint32_t final_feed = static_cast<std::uint32_t>(
      synthetic_position_um(job, printer, index) - (index ? synthetic_position_um(job, printer, index - 1) : 0));
  auto r = session.end_job(final_feed, cancel);
  if (!r) return fail(r.error());
  out.job = std::move(*r);
  out.stream_s = std::chrono::duration<double>(Clock::now() - t0).count();
  out.throughput_MBps = out.stream_s > 0 ? static_cast<double>(out.data_bytes) / out.stream_s / 1e6 : 0;
  return out;
}

}  // namespace tp::host
