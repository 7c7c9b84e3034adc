// host/daemon/crash_guard.cpp: fatal-signal handler that leaves a crash marker behind.
#include "host/daemon/crash_guard.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <fstream>

namespace tp::host {

namespace {

std::atomic<std::int64_t> g_job{0};
char g_marker[4096] = {0};

// Writes the decimal digits of v into buf (no allocation, no locale); returns the length.
size_t format_int(std::int64_t v, char* buf) {
  char tmp[24];
  size_t n = 0;
  bool neg = v < 0;
  std::uint64_t u = neg ? static_cast<std::uint64_t>(-(v + 1)) + 1 : static_cast<std::uint64_t>(v);
  do {
    tmp[n++] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u);
  size_t len = 0;
  if (neg) buf[len++] = '-';
  while (n) buf[len++] = tmp[--n];
  return len;
}

void on_fatal(int sig) {
  const std::int64_t job = g_job.load();
  if (job != 0 && g_marker[0] != '\0') {
    int fd = ::open(g_marker, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd >= 0) {
      char line[64];
      size_t n = format_int(job, line);
      line[n++] = ' ';
      n += format_int(sig, line + n);
      line[n++] = '\n';
      ssize_t w = ::write(fd, line, n);
      (void)w;
      ::fsync(fd);
      ::close(fd);
    }
  }
  // Die of the same signal, so the exit status and core dump are what they would have been.
  std::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void install_crash_guard(const std::filesystem::path& marker) {
  const std::string s = marker.string();
  if (s.size() >= sizeof g_marker) return;
  std::memcpy(g_marker, s.c_str(), s.size() + 1);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, on_fatal);
}

void set_crash_guard_job(std::int64_t job_id) { g_job.store(job_id); }

std::optional<CrashMarker> take_crash_marker(const std::filesystem::path& marker) {
  std::error_code ec;
  if (!std::filesystem::exists(marker, ec)) return std::nullopt;
  CrashMarker m;
  std::ifstream in(marker);
  bool ok = static_cast<bool>(in >> m.job_id >> m.signal);
  in.close();
  std::filesystem::remove(marker, ec);
  if (!ok || m.job_id <= 0) return std::nullopt;
  return m;
}

std::string signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    default: return "signal " + std::to_string(sig);
  }
}

}  // namespace tp::host
