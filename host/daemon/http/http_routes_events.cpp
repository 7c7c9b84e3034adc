// host/daemon/http/http_routes_events.cpp: GET /api/v1/events (Server-Sent Events from the
// daemon's event log, replayed from Last-Event-ID) and GET /api/v1/printer.
#include <charconv>

#include "host/common/text.h"
#include "host/daemon/http/internal/http_impl.h"

namespace tp::host::http {

using nlohmann::json;

namespace {

std::optional<std::uint64_t> parse_u64(const std::string& v) {
  std::uint64_t n = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || p != v.data() + v.size()) return std::nullopt;
  return n;
}

}  // namespace

void add_event_routes(HttpServer::Impl& im) {
  HttpServer::Impl* p = &im;

  im.server->Get("/api/v1/printer", [p](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, p->backend.printer_status ? p->backend.printer_status() : json::object());
  });

  im.server->Get("/api/v1/events", [p](const httplib::Request& req, httplib::Response& res) {
    if (!p->backend.events) return send_error(res, 503, "no event log");
    // Where to start: after Last-Event-ID (a reconnect), after ?after=N, or from now.
    std::uint64_t after = p->backend.events->last_seq();
    for (const char* key : {"after"}) {
      if (!req.has_param(key)) continue;
      auto n = parse_u64(req.get_param_value(key));
      if (!n) return send_error(res, 400, "query \"after\" must be a non-negative integer");
      after = *n;
    }
    if (req.has_header("Last-Event-ID")) {
      auto n = parse_u64(req.get_header_value("Last-Event-ID"));
      if (!n) return send_error(res, 400, "Last-Event-ID must be an event's sequence number");
      after = *n;
    }
    std::int64_t job = 0;
    if (req.has_param("job")) {
      auto n = parse_u64(req.get_param_value("job"));
      if (!n || *n == 0) return send_error(res, 400, "query \"job\" must be a job id");
      job = static_cast<std::int64_t>(*n);
    }
    res.set_header("Cache-Control", "no-cache");
    res.set_header("X-Accel-Buffering", "no");
    auto first = std::make_shared<bool>(true);
    res.set_chunked_content_provider(
        "text/event-stream", [p, after, job, first](size_t, httplib::DataSink& sink) mutable {
          if (p->stopping.load()) {
            sink.done();
            return true;
          }
          std::string out;
          if (*first) {
            out = "retry: 1000\n: printd events after " + std::to_string(after) + "\n\n";
            *first = false;
          }
          EventBatch b = p->backend.events->read_after(after, 256, std::chrono::milliseconds(
                                                                       out.empty() ? p->config.sse_keepalive_ms : 0));
          // Events older than the log keeps are gone: say so, so a client reloads the job list.
          if (b.gap)
            out += "event: gap\ndata: " + dump_json(json{{"after", after}, {"first_kept", b.first_kept}}) + "\n\n";
          for (const auto& e : b.events) {
            after = e.seq;
            if (job == 0 || e.job_id == job || e.job_id == 0) out += to_sse(e);
          }
          if (out.empty()) out = ": keepalive\n\n";
          // A client that stopped reading fails this write at the write timeout; only its own
          // thread waited.
          return sink.write(out.data(), out.size());
        });
  });
}

}  // namespace tp::host::http
