// host/daemon/http/http_server.h: printd's HTTP API (docs/api.yaml) on cpp-httplib: jobs, files,
// printer and Server-Sent Events, with TLS and bearer tokens when it listens beyond loopback.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "host/common/error.h"
#include "host/daemon/events/event_log.h"
#include "host/store/job_store.h"

namespace tp::host {

/// How the HTTP API listens and what it allows (printd --listen, --tls-*, --http-*).
struct HttpConfig {
  std::string listen = "127.0.0.1:8631";  ///< host:port; "off" = no HTTP API
  std::filesystem::path tls_cert;         ///< PEM; with tls_key, serve HTTPS
  std::filesystem::path tls_key;
  bool require_token = false;             ///< forced on when listening beyond loopback
  std::size_t max_upload_bytes = 512ull << 20;  ///< one POST /api/v1/jobs body
  int max_concurrent_uploads = 4;         ///< more at once are answered 503
  int read_timeout_ms = 10000;            ///< a client must keep sending within this
  int write_timeout_ms = 10000;           ///< and keep reading what it asked for
  int threads = 64;                       ///< connections served at once; more wait for a thread
  int sse_keepalive_ms = 15000;           ///< a comment line on an idle event stream this often
  std::filesystem::path console_dir;      ///< the operator console's assets (docs/console.md); empty = none
  std::filesystem::path three_dir = "/usr/share/javascript/three";  ///< libjs-three, served at /vendor/three/
};

/// A parsed --listen value.
struct ListenAddress {
  std::string host;
  int port = 0;
  bool loopback = false;  ///< 127.0.0.0/8, ::1 or "localhost"
};

/// Parses "host:port" or "[v6]:port". Fails naming the value when it is not one.
[[nodiscard]] Result<ListenAddress> parse_listen(const std::string& text);

/// What the API needs of the daemon.
struct HttpBackend {
  /// The daemon's request handler, the same one the control socket uses (request_handler.h):
  /// one JSON request in, one JSON reply out.
  std::function<std::string(JobStore& store, const std::string& request)> request;
  std::filesystem::path db_path;     ///< jobs.db: jobs and tokens
  std::filesystem::path upload_dir;  ///< scratch for uploads (inside the state directory)
  EventLog* events = nullptr;
  /// GET /api/v1/printer's object.
  std::function<nlohmann::json()> printer_status;
};

/// A running HTTP API; the destructor stops it and waits for its threads.
class HttpServer {
 public:
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  /// Binds and starts serving on threads of its own. Refuses (kDaemon) a non-loopback address
  /// without TLS, unreadable TLS files, and a port that cannot be bound.
  [[nodiscard]] static Result<std::unique_ptr<HttpServer>> start(const HttpConfig& config, HttpBackend backend);

  /// The port actually bound (for --listen host:0).
  [[nodiscard]] int port() const;
  /// Whether clients must send a bearer token.
  [[nodiscard]] bool requires_token() const;

  struct Impl;

 private:
  explicit HttpServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::host
