// host/daemon/hot_folder.h: watches a hot folder and reports entries that have stopped changing.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <vector>

namespace tp::host {

/// A folder where operators and cells drop jobs (a folder with job.json, or a .zip). An entry is
/// ready once its size and modification time held still across scans `settle` apart, so a job
/// still being copied in is never taken half-written. done/ and failed/ hold finished entries.
class HotFolder {
 public:
  explicit HotFolder(std::filesystem::path dir,
                     std::chrono::milliseconds settle = std::chrono::milliseconds(1000));

  /// Creates the folder and its done/ and failed/ sub-folders.
  bool prepare() const;
  /// Scans and returns the entries that are ready (each once, until it reappears).
  std::vector<std::filesystem::path> scan();

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path done_dir() const { return dir_ / "done"; }
  std::filesystem::path failed_dir() const { return dir_ / "failed"; }

 private:
  struct Seen {
    std::uintmax_t bytes = 0;
    std::filesystem::file_time_type newest;
    std::chrono::steady_clock::time_point since;
  };
  std::filesystem::path dir_;
  std::chrono::milliseconds settle_;
  std::map<std::filesystem::path, Seen> seen_;
};

}  // namespace tp::host
