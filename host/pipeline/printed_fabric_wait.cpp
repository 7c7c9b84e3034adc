// host/pipeline/printed_fabric_wait.cpp: waiting for printsim's fabric images on inotify events
// rather than by polling, with a timeout that fails the job with a clear error.
#include "host/pipeline/internal/printed_fabric_wait.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>
#include <vector>

namespace tp::host::internal {

namespace fs = std::filesystem;

namespace {

/// Longest sleep between looks: a missed event (a file system without inotify, a watch that could
/// not be added) costs at most this, and cancellation is seen within it.
constexpr int kLookInterval_ms = 1000;

// The job id printsim recorded in `dir`/printer.json, or -1 (none, half written, or older than
// `not_before`).
std::int64_t recorded_job(const fs::path& dir, const std::optional<fs::file_time_type>& not_before) {
  std::error_code ec;
  const fs::path file = dir / "printer.json";
  const auto written = fs::last_write_time(file, ec);
  if (ec || (not_before && written < *not_before)) return -1;
  std::ifstream in(file);
  if (!in) return -1;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("job") || !j["job"].is_object()) return -1;
  const auto& id = j["job"]["id"];
  return id.is_number_integer() ? id.get<std::int64_t>() : -1;
}

// Where printsim writes this job's fabric: its output folder itself, or (--job-dirs) the folders
// there named after the job's id.
std::vector<fs::path> fabric_dirs(const fs::path& printsim_dir, std::int64_t job_id) {
  std::vector<fs::path> dirs{printsim_dir};
  std::error_code ec;
  const std::string prefix = std::to_string(job_id) + "-";
  for (fs::directory_iterator it(printsim_dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec) && it->path().filename().string().rfind(prefix, 0) == 0) dirs.push_back(it->path());
  return dirs;
}

/// An inotify instance watching folders for files closed after writing or moved in, and for new
/// folders; closed on destruction. Without inotify (fd < 0) the wait falls back to looking every
/// kLookInterval_ms.
class FolderWatch {
 public:
  FolderWatch() : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {}
  ~FolderWatch() {
    if (fd_ >= 0) close(fd_);
  }
  FolderWatch(const FolderWatch&) = delete;
  FolderWatch& operator=(const FolderWatch&) = delete;

  void watch(const fs::path& dir) {
    if (fd_ < 0 || !watched_.insert(dir.string()).second) return;
    inotify_add_watch(fd_, dir.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE);
  }

  /// Sleeps until an event comes or `ms` milliseconds pass, then drains the events.
  void sleep(int ms) const {
    if (fd_ < 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(ms));
      return;
    }
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, ms) <= 0) return;
    alignas(inotify_event) char buf[4096];
    while (read(fd_, buf, sizeof buf) > 0) {
    }
  }

 private:
  int fd_;
  std::set<std::string> watched_;
};

}  // namespace

Result<PrintedFabric> wait_for_printed_fabric(const PrintedFabricWait& w, const geometry::CancelToken& cancel) {
  std::error_code ec;
  if (!fs::is_directory(w.printsim_dir, ec))
    return fail(ErrorCode::kIo, "printed fabric: printsim's output folder " + w.printsim_dir.string() +
                                    " does not exist (TP_PRINTSIM)");
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(std::max(0.0, w.timeout_s));
  FolderWatch watch;
  for (;;) {
    // Watch before looking, so a file written between the look and the sleep still wakes it.
    const std::vector<fs::path> dirs = fabric_dirs(w.printsim_dir, w.job_id);
    for (const fs::path& dir : dirs) watch.watch(dir);
    for (const fs::path& dir : dirs) {
      if (recorded_job(dir, w.not_before) != w.job_id) continue;
      PrintedFabric found;
      // printsim writes the fabric images first, then printer.json.
      if (fs::exists(dir / "fabric-lab.tif", ec)) {
        found.fabric_lab = dir / "fabric-lab.tif";
      } else {
        found.reason = "printsim recorded job " + std::to_string(w.job_id) + " in " + dir.string() +
                       " without a fabric-lab.tif (run without --no-fabric, with a colorimetric fabric)";
      }
      return found;
    }
    if (cancel.cancelled()) return fail(ErrorCode::kCancelled, "cancelled while waiting for the printed fabric");
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) break;
    watch.sleep(static_cast<int>(std::min<long long>(left, kLookInterval_ms)));
  }
  char timeout[32];
  std::snprintf(timeout, sizeof timeout, "%g", w.timeout_s);
  return fail(ErrorCode::kPrinter, "printsim wrote no printer.json for job " + std::to_string(w.job_id) + " in " +
                                       w.printsim_dir.string() + " (or a <job id>-<name> folder there) within " +
                                       timeout +
                                       " s of the print's end: is printsim still running, and did it print "
                                       "this job?");
}

}  // namespace tp::host::internal
