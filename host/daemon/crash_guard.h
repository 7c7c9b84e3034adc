// host/daemon/crash_guard.h: records which job printd was running when a fatal signal killed it,
// so the next start marks that job failed instead of re-queueing it into a crash loop.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace tp::host {

/// What a crash marker file says.
struct CrashMarker {
  std::int64_t job_id = 0;
  int signal = 0;
};

/// Installs handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT (an uncaught exception ends
/// in abort) that write "<job id> <signal>" to `marker` and then die of the signal as before.
/// Only async-signal-safe calls run in the handler.
void install_crash_guard(const std::filesystem::path& marker);

/// The job the worker is running now (0 = none); read by the signal handler.
void set_crash_guard_job(std::int64_t job_id);

/// Reads and removes a marker left by a crash; nullopt when there is none or it is unreadable.
std::optional<CrashMarker> take_crash_marker(const std::filesystem::path& marker);

/// "SIGABRT" for 6 and so on.
std::string signal_name(int signal);

}  // namespace tp::host
