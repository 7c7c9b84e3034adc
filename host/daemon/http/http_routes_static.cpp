// host/daemon/http/http_routes_static.cpp: the operator console's page and assets at "/" and the
// packaged three.js at /vendor/three/, with MIME types, validators and the job files' path rules.
#include <sys/stat.h>

#include <fstream>

#include "host/daemon/http/internal/http_impl.h"
#include "host/daemon/http/job_file_path.h"
#include "host/daemon/http/static_file_path.h"

namespace tp::host::http {

namespace fs = std::filesystem;

namespace {

std::string mime_of(const fs::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json" || ext == ".map") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".woff2") return "font/woff2";
  if (ext == ".txt" || ext == ".md") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

// A weak validator from size and modification time: a changed file gets a new one.
std::string etag_of(const struct stat& st) {
  return "W/\"" + std::to_string(st.st_size) + "-" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec / 1000000) + "\"";
}

// Sends `file` (already resolved inside its root) with its MIME type and cache policy, or 304
// when the client's If-None-Match is the file's validator.
void send_file(const httplib::Request& req, httplib::Response& res, const fs::path& file, const char* cache_control) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return send_error(res, 404, "no file '" + req.path + "'");
  const std::string etag = etag_of(st);
  res.set_header("Cache-Control", cache_control);
  res.set_header("ETag", etag);
  res.set_header("X-Content-Type-Options", "nosniff");
  if (req.get_header_value("If-None-Match") == etag) {
    res.status = 304;
    return;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) return send_error(res, 404, "file '" + req.path + "' cannot be read");
  std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  res.status = 200;
  res.set_content(std::move(body), mime_of(file));
}

// A refused or missing asset: 400 for a name that could leave the folder, else 404.
void send_refusal(httplib::Response& res, const Error& error) {
  send_error(res, error.code == ErrorCode::kUnsafePath ? 400 : 404, error.message);
}

}  // namespace

void add_static_routes(HttpServer::Impl& im) {
  httplib::Server& svr = *im.server;
  const fs::path console = im.config.console_dir;
  const fs::path three = im.config.three_dir;
  const std::string missing =
      "the operator console is not installed: printd found no index.html; give "
      "--console-dir DIR (docs/console.md)";

  // The page itself is revalidated on every load, so an upgrade shows at once.
  svr.Get("/", [console, missing](const httplib::Request& req, httplib::Response& res) {
    if (console.empty()) return send_error(res, 404, missing);
    auto file = job_file_path(console, "index.html");
    if (!file) return send_error(res, 404, missing);
    send_file(req, res, *file, "no-cache");
  });

  // three.js as Debian installs it; a library changes only with its package, so a day's caching.
  svr.Get(R"(/vendor/three/(.+))", [three](const httplib::Request& req, httplib::Response& res) {
    if (three.empty()) return send_error(res, 404, "three.js is not served (printd --three-dir)");
    auto file = vendor_file_path(three, req.matches[1]);
    if (!file) return send_refusal(res, file.error());
    send_file(req, res, *file, "public, max-age=86400");
  });

  // Every other path outside /api/ is a console asset (studio/ included), no symlinks followed.
  svr.Get(R"(/((?!api/|vendor/).+))", [console, missing](const httplib::Request& req, httplib::Response& res) {
    if (console.empty()) return send_error(res, 404, missing);
    std::string name = req.matches[1];
    if (name.ends_with('/')) name += "index.html";  // a folder's page, e.g. /studio/
    auto file = job_file_path(console, name);
    if (!file) return send_refusal(res, file.error());
    send_file(req, res, *file, "no-cache");
  });
}

}  // namespace tp::host::http
