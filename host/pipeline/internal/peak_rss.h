// host/pipeline/internal/peak_rss.h: the process's resident memory around a stage (Linux
// /proc/self/status), so report.json can show the RIP's peak memory against the job's size.
#pragma once

#include <optional>

namespace tp::host::internal {

/// Current resident set (VmRSS) in MiB, if /proc tells.
[[nodiscard]] std::optional<double> resident_mib();
/// Peak resident set (VmHWM) in MiB since the process started or the last reset_peak_resident().
[[nodiscard]] std::optional<double> peak_resident_mib();
/// Starts a new peak (writes 5 to /proc/self/clear_refs); false where the kernel refuses.
bool reset_peak_resident();

}  // namespace tp::host::internal
