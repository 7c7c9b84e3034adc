// host/daemon/control_socket.cpp: UNIX-socket plumbing for the daemon and its clients.
#include "host/daemon/control_socket.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <utility>

namespace tp::host {

namespace {

constexpr size_t kMaxReplyBytes = 64 << 20;

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

// Reads until '\n' (not included) or EOF, bounded in size and in total time (a client that
// trickles one byte at a time is cut off at the deadline like one that sends nothing).
Result<std::string> read_line(int fd, int timeout_ms, size_t max_bytes, const char* what) {
  std::string line;
  char buf[4096];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd, POLLIN, 0};
    int r = left.count() <= 0 ? 0 : ::poll(&p, 1, static_cast<int>(left.count()));
    if (r == 0) return fail(ErrorCode::kDaemon, std::string("timed out after ") + std::to_string(timeout_ms) + " ms waiting for " + what);
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
    if (line.size() > max_bytes)
      return fail(ErrorCode::kDaemon, std::string(what) + " longer than " + std::to_string(max_bytes) + " bytes");
  }
}

bool write_all(int fd, const std::string& data) {
  size_t off = 0;
  while (off < data.size()) {
    ssize_t n = ::send(fd, data.data() + off, data.size() - off, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) {
        // A non-blocking client socket whose buffer is full: wait a little for the reader.
        pollfd p{fd, POLLOUT, 0};
        if (::poll(&p, 1, 2000) > 0) continue;
      }
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
  auto reply = write_all(fd, request + "\n") ? read_line(fd, timeout_ms, kMaxReplyBytes, "a reply")
                                             : Result<std::string>(fail(ErrorCode::kDaemon, "send failed"));
  ::close(fd);
  return reply;
}

ControlSocket::ControlSocket(ControlSocket&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), path_(std::move(o.path_)), clients_(std::move(o.clients_)) {}
ControlSocket& ControlSocket::operator=(ControlSocket&& o) noexcept {
  if (this != &o) {
    reap(true);
    if (fd_ >= 0) { ::close(fd_); ::unlink(path_.c_str()); }
    fd_ = std::exchange(o.fd_, -1);
    path_ = std::move(o.path_);
    clients_ = std::move(o.clients_);
  }
  return *this;
}
ControlSocket::~ControlSocket() {
  // Every client thread ends within its request timeout plus its handler's time.
  reap(true);
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
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return fail(ErrorCode::kDaemon, std::string("socket: ") + std::strerror(errno));
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&*addr), sizeof *addr) != 0 || ::listen(fd, 64) != 0) {
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

void ControlSocket::reap(bool all) {
  for (auto it = clients_.begin(); it != clients_.end();) {
    if (all || it->done->load()) {
      if (it->thread.joinable()) it->thread.join();
      it = clients_.erase(it);
    } else {
      ++it;
    }
  }
}

int ControlSocket::active_clients() const {
  int n = 0;
  for (const auto& c : clients_) n += c.done->load() ? 0 : 1;
  return n;
}

int ControlSocket::serve(int timeout_ms, const std::function<std::string(const std::string&)>& handler,
                         const ClientLimits& limits) {
  reap(false);
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, timeout_ms) <= 0) return 0;
  int accepted = 0;
  // Take every client waiting now; the listening socket is non-blocking for this loop.
  for (;;) {
    int c = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
    if (c < 0) break;
    ++accepted;
    if (active_clients() >= limits.max_clients) {
      write_all(c, std::string(R"({"ok":false,"error":"printd is busy: )") + std::to_string(limits.max_clients) +
                       " clients are being served; try again\"}\n");
      ::close(c);
      continue;
    }
    auto done = std::make_shared<std::atomic<bool>>(false);
    std::thread t([c, done, &handler, limits] {
      auto line = read_line(c, limits.request_timeout_ms, limits.max_request_bytes, "a request line");
      std::string reply;
      if (line) {
        reply = handler(*line);
      } else {
        reply = std::string(R"({"ok":false,"error":")") + line.error().message + "; connection dropped\"}";
      }
      // The client gets the rest of its time budget to take the reply; a full socket buffer
      // of a client that does not read must not hold this thread for ever.
      pollfd wp{c, POLLOUT, 0};
      if (::poll(&wp, 1, limits.request_timeout_ms) > 0) write_all(c, reply + "\n");
      ::close(c);
      done->store(true);
    });
    clients_.push_back(Client{std::move(t), done});
  }
  return accepted;
}

}  // namespace tp::host
