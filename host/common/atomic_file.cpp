// host/common/atomic_file.cpp: temp-file-and-rename output with every write and sync checked.
#include "host/common/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace tp::host {

namespace fs = std::filesystem;

namespace {

long long g_write_budget = -1;

const char* errno_name(int e) {
  switch (e) {
    case ENOSPC: return "ENOSPC";
    case EDQUOT: return "EDQUOT";
    case EACCES: return "EACCES";
    case EPERM: return "EPERM";
    case ENOENT: return "ENOENT";
    case EROFS: return "EROFS";
    case EIO: return "EIO";
    case EEXIST: return "EEXIST";
    case EISDIR: return "EISDIR";
    case ENOTDIR: return "ENOTDIR";
    case EMFILE: return "EMFILE";
    case EFBIG: return "EFBIG";
    default: return nullptr;
  }
}

// write(2) in a loop; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
  size_t off = 0;
  while (off < bytes.size()) {
    size_t want = bytes.size() - off;
    if (g_write_budget >= 0) {
      if (g_write_budget == 0) return ENOSPC;
      want = std::min<size_t>(want, static_cast<size_t>(g_write_budget));
    }
    ssize_t n = ::write(fd, bytes.data() + off, want);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (g_write_budget >= 0) g_write_budget -= n;
    off += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

std::string errno_text(int e) {
  std::string s = std::strerror(e);
  if (const char* n = errno_name(e)) s += std::string(" (") + n + ")";
  return s;
}

void set_write_budget_for_tests(long long bytes) { g_write_budget = bytes; }

fs::path temp_path_for(const fs::path& path) {
  // The extension stays last: writers in other layers pick the file format by it.
  return path.parent_path() /
         ("." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) + path.extension().string());
}

Status write_file_atomic(const fs::path& path, std::string_view bytes, unsigned mode) {
  const fs::path tmp = temp_path_for(path);
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, mode);
  if (fd < 0) return fail(ErrorCode::kIo, path.string() + ": cannot create: " + errno_text(errno));
  int e = write_all(fd, bytes);
  if (e == 0 && ::fsync(fd) != 0) e = errno;
  if (::close(fd) != 0 && e == 0) e = errno;
  if (e == 0) ::fchmodat(AT_FDCWD, tmp.c_str(), mode, 0);
  if (e == 0 && ::rename(tmp.c_str(), path.c_str()) != 0) e = errno;
  if (e != 0) {
    ::unlink(tmp.c_str());
    return fail(ErrorCode::kIo, path.string() + ": " + errno_text(e));
  }
  return {};
}

Status write_via_temp(const fs::path& path, const std::function<Status(const fs::path& temp)>& writer) {
  const fs::path tmp = temp_path_for(path);
  std::error_code ec;
  Status st = writer(tmp);
  if (st) {
    // A writer that swallowed a write error leaves an empty or missing file: never rename that.
    const auto bytes = fs::file_size(tmp, ec);
    if (ec || bytes == 0) st = fail(ErrorCode::kIo, path.string() + ": the writer left no data (disk full?)");
  }
  if (st) {
    int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
    int e = fd < 0 ? errno : (::fsync(fd) != 0 ? errno : 0);
    if (fd >= 0) ::close(fd);
    if (e == 0 && ::rename(tmp.c_str(), path.c_str()) != 0) e = errno;
    if (e != 0) st = fail(ErrorCode::kIo, path.string() + ": " + errno_text(e));
  } else if (st.error().message.find(path.string()) == std::string::npos) {
    // Writers name the file they were given (the temporary one): name the real output instead.
    std::string m = st.error().message;
    const std::string t = tmp.string();
    for (size_t at = m.find(t); at != std::string::npos; at = m.find(t)) m.replace(at, t.size(), path.string());
    if (m.find(path.string()) == std::string::npos) m = path.string() + ": " + m;
    st = fail(st.error().code, m);
  }
  if (!st) fs::remove(tmp, ec);
  return st;
}

}  // namespace tp::host
