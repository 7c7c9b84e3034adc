// host/daemon/http/http_routes_upload.cpp: POST /api/v1/jobs: the upload is streamed to a scratch
// file or folder under the state directory, within the size and concurrency caps, then submitted
// through the daemon's shared handler, which checks it as every package is checked.
#include <spdlog/spdlog.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "host/common/text.h"
#include "host/daemon/http/internal/http_impl.h"
#include "host/daemon/http/validation_list.h"

namespace tp::host::http {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Holds one of the concurrent-upload places for the request's lifetime.
class UploadSlot {
 public:
  UploadSlot(std::atomic<int>& n, int max) : n_(n) { ok_ = n_.fetch_add(1) < max; }
  ~UploadSlot() { n_.fetch_sub(1); }
  UploadSlot(const UploadSlot&) = delete;
  UploadSlot& operator=(const UploadSlot&) = delete;
  bool ok() const { return ok_; }

 private:
  std::atomic<int>& n_;
  bool ok_;
};

// A multipart file name as a relative path inside the upload folder: plain parts only.
std::optional<fs::path> safe_relative(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.find('\\') != std::string::npos ||
      name.find('\0') != std::string::npos)
    return std::nullopt;
  fs::path out;
  size_t start = 0;
  while (start <= name.size()) {
    size_t slash = name.find('/', start);
    if (slash == std::string::npos) slash = name.size();
    const std::string part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == "..") return std::nullopt;
    out /= part;
    start = slash + 1;
  }
  return out;
}

bool truthy(const std::string& v) { return v == "1" || v == "true" || v == "yes"; }

}  // namespace

void add_upload_route(HttpServer::Impl& im) {
  HttpServer::Impl* p = &im;
  im.server->Post("/api/v1/jobs", [p](const httplib::Request& req, httplib::Response& res,
                                      const httplib::ContentReader& reader) {
    UploadSlot slot(p->uploads, p->config.max_concurrent_uploads);
    if (!slot.ok()) {
      res.set_header("Retry-After", "5");
      return send_error(res, 503, "too many uploads at once (at most " +
                                      std::to_string(p->config.max_concurrent_uploads) + "); try again");
    }
    const std::size_t cap = p->config.max_upload_bytes;
    if (req.has_header("Content-Length") && std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10) > cap)
      return send_error(res, 413, "upload larger than " + std::to_string(cap) + " bytes (--http-max-upload-mb)");

    std::error_code ec;
    fs::create_directories(p->backend.upload_dir, ec);
    const fs::path base = fs::absolute(p->backend.upload_dir) / ("upload-" + std::to_string(::getpid()) + "-" +
                                                   std::to_string(p->upload_serial.fetch_add(1)));
    struct Cleanup {
      fs::path path;
      ~Cleanup() {
        std::error_code e;
        fs::remove_all(path, e);
      }
    } cleanup{base};

    std::size_t total = 0;
    std::string refusal;
    bool reprint = req.has_param("reprint") && truthy(req.get_param_value("reprint"));
    fs::path package;
    if (req.is_multipart_form_data()) {
      // One .zip part becomes the package; other file parts are a folder's files (their names
      // relative paths, as a browser sends a folder); a "reprint" field counts like the query.
      std::ofstream out;
      std::string field;
      std::string field_value;
      int zip_parts = 0, folder_parts = 0;
      fs::create_directories(base / "job", ec);
      const bool read_ok = reader(
          [&](const httplib::MultipartFormData& part) {
            out.close();
            if (field == "reprint") reprint = reprint || truthy(field_value);
            field = part.name;
            field_value.clear();
            if (part.filename.empty()) return true;
            const std::string fname = part.filename;
            if (fname.size() > 4 && fname.substr(fname.size() - 4) == ".zip" && fname.find('/') == std::string::npos) {
              ++zip_parts;
              package = base.string() + ".zip";
              out.open(package, std::ios::binary);
            } else {
              auto rel = safe_relative(fname);
              if (!rel) {
                refusal = "upload part '" + fname + "': not a plain relative path";
                return false;
              }
              ++folder_parts;
              fs::create_directories((base / "job" / *rel).parent_path(), ec);
              out.open(base / "job" / *rel, std::ios::binary);
            }
            if (!out) refusal = "upload part '" + fname + "': cannot be stored";
            return static_cast<bool>(out);
          },
          [&](const char* data, size_t n) {
            total += n;
            if (total > cap) {
              refusal = "upload larger than " + std::to_string(cap) + " bytes";
              return false;
            }
            if (out.is_open()) out.write(data, static_cast<std::streamsize>(n));
            else if (field_value.size() < 16) field_value.append(data, std::min<size_t>(n, 16));
            return true;
          });
      out.close();
      if (field == "reprint") reprint = reprint || truthy(field_value);
      if (!read_ok || !refusal.empty())
        return send_error(res, total > cap ? 413 : 400, refusal.empty() ? "upload interrupted" : refusal);
      if (zip_parts + (folder_parts > 0 ? 1 : 0) != 1)
        return send_error(res, 400, "a multipart upload holds one .zip or the files of one folder");
      if (folder_parts > 0) package = base / "job";
    } else {
      const std::string type = req.get_header_value("Content-Type");
      if (type != "application/zip" && type != "application/octet-stream")
        return send_error(res, 415, "send the job as application/zip or multipart/form-data");
      package = base.string() + ".zip";
      std::ofstream out(package, std::ios::binary);
      const bool read_ok = reader([&](const char* data, size_t n) {
        total += n;
        if (total > cap) return false;
        out.write(data, static_cast<std::streamsize>(n));
        return static_cast<bool>(out);
      });
      if (!read_ok || !out) return send_error(res, total > cap ? 413 : 400,
                                              total > cap ? "upload larger than " + std::to_string(cap) + " bytes"
                                                          : "upload interrupted or not stored");
    }
    cleanup.path = base;  // the folder, and the .zip beside it below
    struct ZipCleanup {
      fs::path path;
      ~ZipCleanup() {
        std::error_code e;
        fs::remove(path, e);
      }
    } zip_cleanup{base.string() + ".zip"};

    JobStore* store = p->store();
    if (!store) return send_error(res, 503, "job store unavailable");
    json reply = json::parse(
        p->backend.request(*store, dump_json(json{{"op", "submit"}, {"package", package.string()}, {"reprint", reprint}})),
        nullptr, false);
    if (reply.is_discarded() || !reply.is_object()) return send_error(res, 500, "unreadable reply from the daemon");
    if (!reply.value("ok", false)) {
      // The package was refused: the same messages as `printctl validate`, one entry each.
      const std::string error = reply.value("error", std::string("refused"));
      return send_json(res, 422, json{{"error", error}, {"problems", validation_list(error)}});
    }
    reply.erase("ok");
    send_json(res, reply.value("duplicate", false) ? 200 : 201, reply);
  });
}

}  // namespace tp::host::http
