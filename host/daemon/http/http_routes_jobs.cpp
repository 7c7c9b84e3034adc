// host/daemon/http/http_routes_jobs.cpp: the job routes of the HTTP API; each is a request to the
// daemon's shared handler (requests/request_handler.h), so job logic is written once.
#include <charconv>
#include <fstream>
#include <optional>

#include "host/common/text.h"
#include "host/daemon/http/internal/http_impl.h"
#include "host/daemon/http/job_file_path.h"

namespace tp::host::http {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// An optional non-negative integer query parameter; nullopt and a 400 answer when malformed.
std::optional<std::int64_t> int_param(const httplib::Request& req, httplib::Response& res, const char* name,
                                      std::int64_t fallback) {
  if (!req.has_param(name)) return fallback;
  const std::string v = req.get_param_value(name);
  std::int64_t n = 0;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || p != v.data() + v.size() || n < 0) {
    send_error(res, 400, std::string("query \"") + name + "\" must be a non-negative integer");
    return std::nullopt;
  }
  return n;
}

std::optional<std::int64_t> job_id(const httplib::Request& req, httplib::Response& res) {
  std::int64_t id = 0;
  const std::string v = req.matches[1];
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), id);
  if (ec != std::errc() || id <= 0) {
    send_error(res, 404, "no job " + v);
    return std::nullopt;
  }
  return id;
}

// The output folder of job `id` from the store; answers 503 or 404 (and returns nothing) otherwise.
std::optional<fs::path> job_out_dir(HttpServer::Impl& im, std::int64_t id, httplib::Response& res) {
  JobStore* store = im.store();
  if (!store) {
    send_error(res, 503, "job store unavailable");
    return std::nullopt;
  }
  auto rec = store->get(id);
  if (!rec || !*rec) {
    send_error(res, 404, "no job " + std::to_string(id));
    return std::nullopt;
  }
  return (*rec)->out_dir;
}

std::string content_type_of(const fs::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".json") return "application/json";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".dxf") return "image/vnd.dxf";
  if (ext == ".obj" || ext == ".mtl" || ext == ".txt") return "text/plain; charset=utf-8";
  if (ext == ".tif" || ext == ".tiff") return "image/tiff";
  if (ext == ".html") return "text/html; charset=utf-8";
  return "application/octet-stream";
}

// The job's report.json, when it has one that is small enough to inline.
json read_report(const fs::path& out_dir) {
  std::error_code ec;
  const fs::path p = out_dir / "report.json";
  const auto size = fs::file_size(p, ec);
  if (ec || size > (8u << 20)) return nullptr;
  std::ifstream in(p, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  json j = json::parse(text, nullptr, false);
  return j.is_discarded() ? json(nullptr) : j;
}

}  // namespace

void add_job_routes(HttpServer::Impl& im) {
  httplib::Server& svr = *im.server;
  HttpServer::Impl* p = &im;

  svr.Get("/api/v1/jobs", [p](const httplib::Request& req, httplib::Response& res) {
    auto limit = int_param(req, res, "limit", 50);
    if (!limit) return;
    auto offset = int_param(req, res, "offset", 0);
    if (!offset) return;
    json r = {{"op", "status"}, {"limit", *limit}, {"offset", *offset}};
    if (req.has_param("state")) r["state"] = req.get_param_value("state");
    answer(*p, res, r, 200);
  });

  svr.Get(R"(/api/v1/jobs/(\d+))", [p](const httplib::Request& req, httplib::Response& res) {
    auto id = job_id(req, res);
    if (!id) return;
    answer(*p, res, {{"op", "status"}, {"id", *id}}, 200);
    if (res.status != 200) return;
    // The report's figures (estimate, ink, print) beside the stages, once the job has them.
    JobStore* store = p->store();
    auto rec = store ? store->get(*id) : Result<std::optional<JobRecord>>(std::optional<JobRecord>{});
    if (!rec || !*rec) return;
    json body = json::parse(res.body, nullptr, false);
    json report = read_report((*rec)->out_dir);
    if (!report.is_null() && report.value("job_id", 0LL) == *id) {
      report.erase("stages");
      body["job"]["report"] = report;
    }
    send_json(res, 200, body);
  });

  svr.Delete(R"(/api/v1/jobs/(\d+))", [p](const httplib::Request& req, httplib::Response& res) {
    auto id = job_id(req, res);
    if (!id) return;
    answer(*p, res, {{"op", "cancel"}, {"id", *id}}, 200);
  });

  svr.Post(R"(/api/v1/jobs/(\d+)/reprint)", [p](const httplib::Request& req, httplib::Response& res) {
    auto id = job_id(req, res);
    if (!id) return;
    answer(*p, res, {{"op", "reprint"}, {"id", *id}}, 201);
  });

  svr.Get(R"(/api/v1/jobs/(\d+)/files)", [p](const httplib::Request& req, httplib::Response& res) {
    auto id = job_id(req, res);
    if (!id) return;
    auto out = job_out_dir(*p, *id, res);
    if (!out) return;
    // Regular files only, symlinks neither followed nor listed.
    json files = json::array();
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(*out, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
      if (it->is_symlink(ec) || !it->is_regular_file(ec)) continue;
      files.push_back({{"name", printable_utf8(fs::relative(it->path(), *out, ec).generic_string())},
                       {"bytes", it->file_size(ec)}});
    }
    send_json(res, 200, json{{"id", *id}, {"files", files}});
  });

  svr.Get(R"(/api/v1/jobs/(\d+)/files/(.+))", [p](const httplib::Request& req, httplib::Response& res) {
    auto id = job_id(req, res);
    if (!id) return;
    auto out = job_out_dir(*p, *id, res);
    if (!out) return;
    auto file = job_file_path(*out, req.matches[2]);
    if (!file) return send_error(res, file.error().code == ErrorCode::kUnsafePath ? 400 : 404, file.error().message);
    std::error_code ec;
    const auto size = fs::file_size(*file, ec);
    if (ec) return send_error(res, 404, "no file '" + std::string(req.matches[2]) + "' among the job's outputs");
    // Streamed in pieces: a fabric PNG can be large, and a slow reader holds only this thread.
    auto in = std::make_shared<std::ifstream>(*file, std::ios::binary);
    if (!*in) return send_error(res, 404, "file '" + std::string(req.matches[2]) + "' cannot be read");
    res.set_content_provider(static_cast<size_t>(size), content_type_of(*file),
                             [in](size_t offset, size_t length, httplib::DataSink& sink) {
                               char buf[64 * 1024];
                               in->seekg(static_cast<std::streamoff>(offset));
                               const size_t n = std::min(length, sizeof buf);
                               in->read(buf, static_cast<std::streamsize>(n));
                               const auto got = static_cast<size_t>(in->gcount());
                               return got > 0 && sink.write(buf, got);
                             });
  });
}

}  // namespace tp::host::http
