// host/daemon/control_socket.cpp: UNIX-socket plumbing for the daemon and its clients.
#include "host/daemon/control_socket.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace tp::host {

namespace {

constexpr size_t kMaxLineBytes = 1 << 20;

Result<sockaddr_un> make_addr(const std::filesystem::path& path) {
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string s = path.string();
  if (s.size() >= sizeof(addr.sun_path))
    return fail(ErrorCode::kDaemon, s + ": socket path longer than " + std::to_string(sizeof(addr.sun_path) - 1) +
                                        " bytes");
  std::memcpy(addr.sun_path, s.c_str(), s.size() + 1);
  return addr;
}

// Reads until '\n' (not included) or EOF, bounded in size and time.
Result<std::string> read_line(int fd, int timeout_ms) {
  std::string line;
  char buf[4096];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    int r = ::poll(&p, 1, timeout_ms);
    if (r == 0) return fail(ErrorCode::kDaemon, "timed out waiting for a reply");
    if (r < 0) {
      if (errno == EINTR) continue;
      return fail(ErrorCode::kDaemon, std::string("poll: ") + std::strerror(errno));
    }
    ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail(ErrorCode::kDaemon, std::string("read: ") + std::strerror(errno));
    }
    if (n == 0) return line;
    for (ssize_t i = 0; i < n; ++i) {
      if (buf[i] == '\n') return line;
      line += buf[i];
    }
    if (line.size() > kMaxLineBytes) return fail(ErrorCode::kDaemon, "request line too long");
  }
}

bool write_all(int fd, const std::string& data) {
  size_t off = 0;
  while (off < data.size()) {
    ssize_t n = ::send(fd, data.data() + off, data.size() - off, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    off += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

std::filesystem::path default_socket_path(const std::filesystem::path& state_dir) {
  return state_dir / "printd.sock";
}

Result<std::string> socket_request(const std::filesystem::path& socket_path, const std::string& request,
                                   int timeout_ms) {
  auto addr = make_addr(socket_path);
  if (!addr) return std::unexpected(addr.error());
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return fail(ErrorCode::kDaemon, std::string("socket: ") + std::strerror(errno));
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&*addr), sizeof *addr) != 0) {
    int e = errno;
    ::close(fd);
    return fail(ErrorCode::kDaemon, socket_path.string() + ": no daemon is listening (" + std::strerror(e) +
                                        "); start it with printd");
  }
  auto reply = write_all(fd, request + "\n") ? read_line(fd, timeout_ms)
                                             : Result<std::string>(fail(ErrorCode::kDaemon, "send failed"));
  ::close(fd);
  return reply;
}

ControlSocket::ControlSocket(ControlSocket&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), path_(std::move(o.path_)) {}
ControlSocket& ControlSocket::operator=(ControlSocket&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) { ::close(fd_); ::unlink(path_.c_str()); }
    fd_ = std::exchange(o.fd_, -1);
    path_ = std::move(o.path_);
  }
  return *this;
}
ControlSocket::~ControlSocket() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(path_.c_str());
  }
}

Result<ControlSocket> ControlSocket::listen(const std::filesystem::path& path) {
  auto addr = make_addr(path);
  if (!addr) return std::unexpected(addr.error());
  // A socket file that nobody answers on is left over from a crash: remove it.
  if (std::filesystem::exists(std::filesystem::symlink_status(path))) {
    if (socket_request(path, R"({"op":"ping"})", 500))
      return fail(ErrorCode::kDaemon, path.string() + ": another printd is already running here");
    ::unlink(path.c_str());
  }
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return fail(ErrorCode::kDaemon, std::string("socket: ") + std::strerror(errno));
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&*addr), sizeof *addr) != 0 || ::listen(fd, 16) != 0) {
    int e = errno;
    ::close(fd);
    return fail(ErrorCode::kDaemon, path.string() + ": cannot listen: " + std::strerror(e));
  }
  ::chmod(path.c_str(), 0660);
  ControlSocket s;
  s.fd_ = fd;
  s.path_ = path;
  return s;
}

bool ControlSocket::serve_one(int timeout_ms, const std::function<std::string(const std::string&)>& handler) {
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, timeout_ms) <= 0) return false;
  int c = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC);
  if (c < 0) return false;
  auto line = read_line(c, 5000);
  if (line) write_all(c, handler(*line) + "\n");
  ::close(c);
  return true;
}

}  // namespace tp::host
