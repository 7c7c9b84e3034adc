// host/bench/child_process.cpp: fork, pipe the child's figures back, wait4 for its resource usage.
#include "host/bench/child_process.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

namespace {

void write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

}  // namespace

Result<ChildRun> run_in_child(const std::function<Status(const FigureSink&)>& body) {
  int fds[2];
  if (::pipe(fds) != 0) return fail(ErrorCode::kIo, std::string("bench: pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) return fail(ErrorCode::kIo, std::string("bench: fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(fds[0]);
    // Child: report figures line by line; leave without running the parent's exit handlers.
    const int out = fds[1];
    Status s = body([out](std::string_view k, std::string_view v) { write_all(out, fmt::format("{}={}\n", k, v)); });
    if (!s) write_all(out, fmt::format("error={}\n", s.error().message));
    ::close(out);
    ::_exit(s ? 0 : 1);
  }
  ::close(fds[1]);
  std::string text;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buf, static_cast<size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  rusage ru{};
  while (::wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {}

  ChildRun run;
  run.peak_rss_mb = ru.ru_maxrss / 1024.0;
  run.cpu_s = ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 + ru.ru_stime.tv_sec + ru.ru_stime.tv_usec * 1e-6;
  std::string error;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    const std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    const size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    if (line.compare(0, eq, "error") == 0) error = line.substr(eq + 1);
    else run.figures.emplace_back(line.substr(0, eq), line.substr(eq + 1));
  }
  if (WIFSIGNALED(status))
    return fail(ErrorCode::kIo, fmt::format("bench: child died on signal {}", WTERMSIG(status)));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return fail(ErrorCode::kIo, error.empty() ? "bench: child failed" : error);
  return run;
}

}  // namespace tp::rip
