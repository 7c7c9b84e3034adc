// host/daemon/http/http_server.cpp: binding, TLS, bearer-token checks and shared answering helpers
// of printd's HTTP API.
#include "host/daemon/http/http_server.h"

#include <spdlog/spdlog.h>

#include <charconv>
#include <map>

#include "host/common/text.h"
#include "host/daemon/http/internal/http_impl.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

Result<ListenAddress> parse_listen(const std::string& text) {
  const std::string bad = "--listen '" + text + "': expected host:port (e.g. 127.0.0.1:8631 or [::1]:8631)";
  ListenAddress a;
  std::string port;
  if (!text.empty() && text.front() == '[') {
    const size_t close = text.find(']');
    if (close == std::string::npos || close + 1 >= text.size() || text[close + 1] != ':') return fail(ErrorCode::kInvalidArgument, bad);
    a.host = text.substr(1, close - 1);
    port = text.substr(close + 2);
  } else {
    const size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0) return fail(ErrorCode::kInvalidArgument, bad);
    a.host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  auto [p, ec] = std::from_chars(port.data(), port.data() + port.size(), a.port);
  if (ec != std::errc() || p != port.data() + port.size() || a.port < 0 || a.port > 65535 || a.host.empty())
    return fail(ErrorCode::kInvalidArgument, bad);
  a.loopback = a.host == "localhost" || a.host == "::1" || a.host.rfind("127.", 0) == 0;
  return a;
}

JobStore* HttpServer::Impl::store() {
  thread_local std::map<std::string, JobStore> stores;
  auto it = stores.find(backend.db_path.string());
  if (it == stores.end()) {
    auto s = JobStore::open(backend.db_path);
    if (!s) return nullptr;
    it = stores.emplace(backend.db_path.string(), std::move(*s)).first;
  }
  return &it->second;
}

TokenStore* HttpServer::Impl::tokens() {
  thread_local std::map<std::string, TokenStore> stores;
  auto it = stores.find(backend.db_path.string());
  if (it == stores.end()) {
    auto s = TokenStore::open(backend.db_path);
    if (!s) return nullptr;
    it = stores.emplace(backend.db_path.string(), std::move(*s)).first;
  }
  return &it->second;
}

namespace http {

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(dump_json(body), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, json{{"error", printable_utf8(message)}});
}

void answer(HttpServer::Impl& im, httplib::Response& res, const json& request, int ok_status) {
  JobStore* store = im.store();
  if (!store) return send_error(res, 503, "job store unavailable: " + im.backend.db_path.string());
  json reply = json::parse(im.backend.request(*store, dump_json(request)), nullptr, false);
  if (reply.is_discarded() || !reply.is_object()) return send_error(res, 500, "unreadable reply from the daemon");
  if (reply.value("ok", false)) {
    reply.erase("ok");
    return send_json(res, ok_status, reply);
  }
  const std::string error = reply.value("error", std::string("request failed"));
  int status = 400;
  if (error.rfind("no job ", 0) == 0) status = 404;
  else if (error.find("has already ended") != std::string::npos) status = 409;
  send_error(res, status, error);
}

}  // namespace http

namespace {

// Bearer tokens: a read-scoped token may only GET; anything else needs an admin token.
httplib::Server::HandlerResponse check_token(HttpServer::Impl& im, const httplib::Request& req, httplib::Response& res) {
  if (!im.require_token) return httplib::Server::HandlerResponse::Unhandled;
  // The console's page and its scripts are public files; the data they fetch is under /api/.
  if ((req.method == "GET" || req.method == "HEAD") && req.path.rfind("/api/", 0) != 0)
    return httplib::Server::HandlerResponse::Unhandled;
  const std::string auth = req.get_header_value("Authorization");
  const std::string prefix = "Bearer ";
  TokenStore* tokens = im.tokens();
  if (!tokens) {
    http::send_error(res, 503, "token store unavailable");
    return httplib::Server::HandlerResponse::Handled;
  }
  std::optional<TokenRecord> token;
  if (auth.rfind(prefix, 0) == 0) {
    auto t = tokens->check(auth.substr(prefix.size()));
    if (t) token = *t;
  }
  if (!token) {
    res.set_header("WWW-Authenticate", "Bearer realm=\"printd\"");
    http::send_error(res, 401, "a bearer token is required (printctl token add NAME)");
    return httplib::Server::HandlerResponse::Handled;
  }
  if (token->scope == TokenScope::kRead && req.method != "GET" && req.method != "HEAD") {
    http::send_error(res, 403, "token '" + token->name + "' is read-only");
    return httplib::Server::HandlerResponse::Handled;
  }
  return httplib::Server::HandlerResponse::Unhandled;
}

}  // namespace

HttpServer::HttpServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

HttpServer::~HttpServer() {
  impl_->stopping.store(true);
  if (impl_->backend.events) impl_->backend.events->close();
  impl_->server->stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

int HttpServer::port() const { return impl_->port; }
bool HttpServer::requires_token() const { return impl_->require_token; }

Result<std::unique_ptr<HttpServer>> HttpServer::start(const HttpConfig& config, HttpBackend backend) {
  auto addr = parse_listen(config.listen);
  if (!addr) return std::unexpected(addr.error());
  const bool tls = !config.tls_cert.empty() || !config.tls_key.empty();
  if (tls && (config.tls_cert.empty() || config.tls_key.empty()))
    return fail(ErrorCode::kDaemon, "--tls-cert and --tls-key go together");
  if (!addr->loopback && !tls)
    return fail(ErrorCode::kDaemon, "--listen " + config.listen +
                                        ": listening beyond loopback needs TLS (--tls-cert, --tls-key) and "
                                        "bearer tokens (printctl token add)");
  auto im = std::make_unique<Impl>();
  im->config = config;
  im->backend = std::move(backend);
  im->address = *addr;
  im->require_token = config.require_token || !addr->loopback;
  if (tls) {
    for (const auto& f : {config.tls_cert, config.tls_key}) {
      std::error_code ec;
      if (!fs::is_regular_file(f, ec)) return fail(ErrorCode::kDaemon, f.string() + ": no such TLS file");
    }
    auto ssl = std::make_unique<httplib::SSLServer>(config.tls_cert.c_str(), config.tls_key.c_str());
    if (!ssl->is_valid())
      return fail(ErrorCode::kDaemon, config.tls_cert.string() + ", " + config.tls_key.string() +
                                          ": not a usable PEM certificate and private key");
    im->server = std::move(ssl);
  } else {
    im->server = std::make_unique<httplib::Server>();
  }
  httplib::Server& svr = *im->server;
  const int threads = std::max(2, config.threads);
  svr.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  svr.set_read_timeout(std::chrono::milliseconds(config.read_timeout_ms));
  svr.set_write_timeout(std::chrono::milliseconds(config.write_timeout_ms));
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, which would let a second printd
  // bind the same port and take half of the first one's clients.
  svr.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  svr.set_tcp_nodelay(true);
  svr.set_keep_alive_timeout(5);
  svr.set_keep_alive_max_count(1000);
  svr.set_payload_max_length(config.max_upload_bytes + (1 << 20));
  Impl* raw = im.get();
  svr.set_pre_routing_handler([raw](const httplib::Request& req, httplib::Response& res) {
    return check_token(*raw, req, res);
  });
  svr.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "?";
    try {
      if (ep) std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    spdlog::error("printd: http {} {}: internal error: {}", req.method, printable_utf8(req.path), what);
    http::send_error(res, 500, "internal error: " + what);
  });
  svr.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    http::send_error(res, res.status, res.status == 404 ? "no route " + req.method + " " + req.path : "request refused");
  });
  http::add_job_routes(*im);
  http::add_upload_route(*im);
  http::add_event_routes(*im);
  http::add_studio_routes(*im);
  http::add_static_routes(*im);

  if (addr->port == 0) {
    im->port = svr.bind_to_any_port(addr->host);
    if (im->port <= 0) return fail(ErrorCode::kDaemon, "--listen " + config.listen + ": cannot bind");
  } else {
    if (!svr.bind_to_port(addr->host, addr->port))
      return fail(ErrorCode::kDaemon, "--listen " + config.listen + ": cannot bind (in use, or not this host's address)");
    im->port = addr->port;
  }
  im->thread = std::thread([raw] { raw->server->listen_after_bind(); });
  spdlog::info("printd: HTTP API on {}://{}:{}{}", tls ? "https" : "http", addr->host, im->port,
               im->require_token ? " (bearer tokens required)" : "");
  return std::unique_ptr<HttpServer>(new HttpServer(std::move(im)));
}

}  // namespace tp::host
