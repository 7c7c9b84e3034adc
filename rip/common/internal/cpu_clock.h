// rip/common/internal/cpu_clock.h: the calling thread's CPU time, for stage timings that stay honest
// on a machine shared with other work.
#pragma once

#include <time.h>

namespace tp::rip {

/// CPU seconds the calling thread has run (CLOCK_THREAD_CPUTIME_ID): unlike wall time it does not
/// count time the thread waited for a core.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + ts.tv_nsec * 1e-9;
}

}  // namespace tp::rip
