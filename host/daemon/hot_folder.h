// host/daemon/hot_folder.h: watches a hot folder and reports entries that have stopped changing.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <vector>

#include <cstdint>

namespace tp::host {

/// A folder where operators and cells drop jobs (a folder with job.json, or a .zip). An entry is
/// ready once its size and modification time held still for `settle` and no process has one of
/// its files open for writing (checked with a read lease, fcntl F_SETLEASE), so a job still being
/// copied in, even by a copier that pauses, is never taken half-written. Hidden names (".x") are
/// skipped, so a copy to ".name" renamed to "name" is taken at once after the settle time.
/// done/ and failed/ hold finished entries.
class HotFolder {
 public:
  explicit HotFolder(std::filesystem::path dir,
                     std::chrono::milliseconds settle = std::chrono::milliseconds(1000));

  /// Creates the folder and its done/ and failed/ sub-folders.
  bool prepare() const;
  /// Scans and returns the entries that are ready (each once, until it reappears).
  std::vector<std::filesystem::path> scan();

  const std::filesystem::path& dir() const { return dir_; }
  std::chrono::milliseconds settle() const { return settle_; }
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

/// True when some process has `file` open for writing (a read lease cannot be taken). False when
/// it is not, or when the filesystem does not support leases (then only the settle time guards).
bool open_for_writing(const std::filesystem::path& file);

}  // namespace tp::host
