// host/daemon/hot_folder.cpp: settle detection for dropped job packages.
#include "host/daemon/hot_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <set>

namespace tp::host {

namespace fs = std::filesystem;

bool open_for_writing(const fs::path& file) {
  int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  const int r = ::fcntl(fd, F_SETLEASE, F_RDLCK);
  const bool busy = r != 0 && (errno == EAGAIN || errno == EBUSY);
  if (r == 0) ::fcntl(fd, F_SETLEASE, F_UNLCK);
  ::close(fd);
  return busy;
}

HotFolder::HotFolder(fs::path dir, std::chrono::milliseconds settle) : dir_(std::move(dir)), settle_(settle) {}

bool HotFolder::prepare() const {
  std::error_code ec;
  fs::create_directories(done_dir(), ec);
  fs::create_directories(failed_dir(), ec);
  return fs::is_directory(dir_);
}

std::vector<fs::path> HotFolder::scan() {
  std::vector<fs::path> ready;
  std::set<fs::path> present;
  const auto now = std::chrono::steady_clock::now();
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    const fs::path p = e.path();
    const std::string name = p.filename().string();
    // Hidden names are conventionally "still being written" (e.g. rsync temporaries).
    if (name.empty() || name[0] == '.' || name == "done" || name == "failed") continue;
    if (!e.is_directory(ec) && p.extension() != ".zip") continue;
    present.insert(p);

    Seen cur;
    cur.since = now;
    cur.newest = e.last_write_time(ec);
    if (e.is_directory(ec)) {
      for (const auto& f : fs::recursive_directory_iterator(p, ec)) {
        if (f.is_regular_file(ec)) cur.bytes += f.file_size(ec);
        auto t = f.last_write_time(ec);
        if (t > cur.newest) cur.newest = t;
      }
    } else {
      cur.bytes = e.file_size(ec);
    }
    auto it = seen_.find(p);
    if (it == seen_.end() || it->second.bytes != cur.bytes || it->second.newest != cur.newest) {
      seen_[p] = cur;
      continue;
    }
    if (now - it->second.since < settle_) continue;
    // Stable for the settle time; still refused while any file of it is open for writing.
    bool writing = false;
    if (e.is_directory(ec)) {
      int files = 0;
      for (const auto& f : fs::recursive_directory_iterator(p, ec)) {
        if (++files > 10000 || writing) break;
        if (f.is_regular_file(ec)) writing = open_for_writing(f.path());
      }
    } else {
      writing = open_for_writing(p);
    }
    if (writing) {
      it->second.since = now;
      continue;
    }
    ready.push_back(p);
    seen_.erase(it);
  }
  // Forget entries that went away so a re-dropped job is seen afresh.
  for (auto it = seen_.begin(); it != seen_.end();) it = present.count(it->first) ? std::next(it) : seen_.erase(it);
  return ready;
}

}  // namespace tp::host
