// host/daemon/http/internal/http_impl.h: the HTTP server's state and route groups (cpp-httplib
// stays inside host/daemon/http/).
#pragma once

#include <httplib.h>

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "host/daemon/http/http_server.h"
#include "host/store/token_store.h"

namespace tp::host {

class StudioCache;

struct HttpServer::Impl {
  HttpConfig config;
  HttpBackend backend;
  ListenAddress address;
  bool require_token = false;
  std::unique_ptr<httplib::Server> server;
  std::thread thread;
  std::atomic<bool> stopping{false};
  std::atomic<int> uploads{0};
  std::atomic<std::uint64_t> upload_serial{0};
  int port = 0;
  std::shared_ptr<StudioCache> studio;  ///< design-studio garments (http_routes_studio.cpp)

  /// This thread's connection to the job store (SQLite connections are not shared).
  JobStore* store();
  TokenStore* tokens();
};

namespace http {

/// A JSON body with `status`.
void send_json(httplib::Response& res, int status, const nlohmann::json& body);
/// An error body {"error": message} with `status`.
void send_error(httplib::Response& res, int status, const std::string& message);
/// Runs one request through the daemon's shared handler and answers it: `ok_status` with the
/// reply's fields on success, else 404 (no such job), 409 (job already ended) or 400.
void answer(HttpServer::Impl& im, httplib::Response& res, const nlohmann::json& request, int ok_status);

/// GET/DELETE /api/v1/jobs..., POST .../reprint, GET .../files/{name}.
void add_job_routes(HttpServer::Impl& im);
/// POST /api/v1/jobs (application/zip body or multipart: one .zip, or a folder's files).
void add_upload_route(HttpServer::Impl& im);
/// GET /api/v1/events (Server-Sent Events) and GET /api/v1/printer.
void add_event_routes(HttpServer::Impl& im);
/// /api/v1/studio/garments... (design studio) and the studio page at /studio/.
void add_studio_routes(HttpServer::Impl& im);
/// GET / and the console's assets (HttpConfig::console_dir), GET /vendor/three/... (three_dir).
/// Registered last: its catch-all takes every GET outside /api/ no other route matched.
void add_static_routes(HttpServer::Impl& im);

}  // namespace http
}  // namespace tp::host
