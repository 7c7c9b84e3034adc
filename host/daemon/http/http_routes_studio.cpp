// host/daemon/http/http_routes_studio.cpp: the design studio's API (garments sewn into an LRU of
// sessions, uploads, live preview atlases, job packages) and its page at /studio/ with three.js.
#include <spdlog/spdlog.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "host/common/text.h"
#include "host/daemon/http/internal/http_impl.h"
#include "host/daemon/http/validation_list.h"
#include "host/daemon/studio/studio_cache.h"
#include "host/daemon/studio/studio_package.h"
#include "host/daemon/studio/studio_preview.h"

namespace tp::host::http {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::size_t kStudioJsonMaxBytes = 16u << 20;  ///< a design or settings body (max_manifest_bytes)
constexpr std::size_t kStudioGarments = 8;              ///< garments kept at once
constexpr int kStudioSewsAtOnce = 2;

// A validation failure as the API answers it everywhere: 422 with the problems listed.
void send_failure(httplib::Response& res, const Error& e) {
  if (e.code == ErrorCode::kValidation || e.code == ErrorCode::kUnsafePath)
    return send_json(res, 422, json{{"error", printable_utf8(e.message)}, {"problems", validation_list(e.message)}});
  if (e.code == ErrorCode::kPipeline || e.code == ErrorCode::kJob || e.code == ErrorCode::kInvalidArgument)
    return send_json(
        res, 422,
        json{{"error", printable_utf8(e.message)},
             {"problems", json::array({{{"file", ""}, {"pointer", ""}, {"message", printable_utf8(e.message)}}})}});
  send_error(res, 500, e.message);
}

void send_problem(httplib::Response& res, int status, const std::string& pointer, const std::string& message) {
  send_json(res, status,
            json{{"error", printable_utf8(message)},
                 {"problems",
                  json::array({{{"file", "request"}, {"pointer", pointer}, {"message", printable_utf8(message)}}})}});
}

// A plain asset name: letters, digits, '-', '_', '.', not leading with '.', at most 100.
bool plain_name(const std::string& n) {
  if (n.empty() || n.size() > 100 || n.front() == '.') return false;
  for (char c : n)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  return true;
}

std::string extension_of(const std::string& name) {
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos) return "";
  std::string ext = name.substr(dot);
  return plain_name("x" + ext) ? ext : "";
}

// Reads a non-multipart body of at most `cap` bytes; false (answered) when larger or cut short.
bool read_body(const httplib::Request& req, const httplib::ContentReader& reader, std::size_t cap, std::string& out,
               httplib::Response& res) {
  if (req.has_header("Content-Length") &&
      std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10) > cap) {
    send_problem(res, 413, "", "request body larger than " + std::to_string(cap) + " bytes");
    return false;
  }
  bool too_big = false;
  const bool ok = reader([&](const char* data, size_t n) {
    if (out.size() + n > cap) {
      too_big = true;
      return false;
    }
    out.append(data, n);
    return true;
  });
  if (too_big)
    send_problem(res, 413, "", "request body larger than " + std::to_string(cap) + " bytes");
  else if (!ok)
    send_problem(res, 400, "", "request body interrupted");
  return ok && !too_big;
}

// A JSON object body; false (answered 400 naming the position) when it is not one.
bool read_json(const httplib::Request& req, const httplib::ContentReader& reader, json& out, httplib::Response& res) {
  std::string body;
  if (!read_body(req, reader, kStudioJsonMaxBytes, body, res)) return false;
  try {
    out = json::parse(body);
  } catch (const json::parse_error& e) {
    send_problem(res, 400, "", std::string("request body is not JSON: ") + e.what());
    return false;
  }
  if (!out.is_object()) {
    send_problem(res, 400, "", "request body must be a JSON object");
    return false;
  }
  return true;
}

// Multipart parts: (field, filename, bytes), within `cap` bytes in all.
struct Part {
  std::string name, filename, data;
};
bool read_parts(const httplib::ContentReader& reader, std::size_t cap, std::vector<Part>& parts,
                httplib::Response& res) {
  std::size_t total = 0;
  bool too_big = false;
  const bool ok = reader(
      [&](const httplib::MultipartFormData& f) {
        parts.push_back({f.name, f.filename, {}});
        return true;
      },
      [&](const char* data, size_t n) {
        total += n;
        if (total > cap) {
          too_big = true;
          return false;
        }
        parts.back().data.append(data, n);
        return true;
      });
  if (too_big)
    send_problem(res, 413, "", "upload larger than " + std::to_string(cap) + " bytes");
  else if (!ok)
    send_problem(res, 400, "", "multipart upload interrupted");
  return ok && !too_big;
}

bool write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

// The garment section from a multipart garment request; assets written into dir/assets.
bool multipart_garment(const std::vector<Part>& parts, const fs::path& dir, json& section, httplib::Response& res) {
  std::string dress_form;
  for (const Part& p : parts) {
    if (p.name == "pattern" || p.name == "body") {
      if (p.filename.empty()) {
        send_problem(res, 400, "/" + p.name, "part '" + p.name + "' must be a file");
        return false;
      }
      const std::string rel = "assets/" + p.name + extension_of(p.filename);
      if (!write_bytes(dir / rel, p.data)) {
        send_error(res, 500, (dir / rel).string() + ": cannot store the upload");
        return false;
      }
      if (p.name == "pattern")
        section["pattern"] = rel;
      else
        section["body"]["mesh"] = rel;
    } else if (p.name == "body_units") {
      section["body"]["units"] = p.data;
    } else if (p.name == "dress_form") {
      dress_form = p.data;
    } else if (p.name == "size" || p.name == "sample" || p.name == "stitches" || p.name == "pattern_format") {
      section[p.name] = p.data;
    } else {
      send_problem(res, 400, "/" + p.name,
                   "unknown part '" + p.name +
                       "' (pattern, body, body_units, dress_form, size, sample, stitches, pattern_format)");
      return false;
    }
  }
  if (!dress_form.empty()) {
    json df = json::parse(dress_form, nullptr, false);
    if (df.is_discarded() || !df.is_object()) {
      send_problem(res, 400, "/dress_form", "dress_form must be a JSON object of measurements");
      return false;
    }
    section["body"]["dress_form"] = df;
  }
  return true;
}

}  // namespace

void add_studio_routes(HttpServer::Impl& im) {
  HttpServer::Impl* p = &im;
  auto cache = std::make_shared<StudioCache>(
      fs::absolute(p->backend.upload_dir) / ("studio-" + std::to_string(::getpid())), kStudioGarments);
  im.studio = cache;
  const std::string id_re = "/api/v1/studio/garments/([0-9a-f]{16})";

  im.server->Post("/api/v1/studio/garments", [p, cache](const httplib::Request& req, httplib::Response& res,
                                                        const httplib::ContentReader& reader) {
    struct SewSlot {
      std::atomic<int>& n;
      bool ok;
      explicit SewSlot(std::atomic<int>& c) : n(c), ok(c.fetch_add(1) < kStudioSewsAtOnce) {}
      ~SewSlot() { n.fetch_sub(1); }
    } slot(cache->sewing);
    if (!slot.ok) {
      res.set_header("Retry-After", "5");
      return send_error(res, 503, "garments are being sewn already; try again");
    }
    auto session = cache->new_session();
    if (!session) return send_error(res, 500, session.error().message);
    const auto& [id, dir] = *session;
    struct Cleanup {
      fs::path dir;
      bool keep = false;
      ~Cleanup() {
        std::error_code ec;
        if (!keep) fs::remove_all(dir, ec);
      }
    } cleanup{dir};
    json section = json::object();
    if (req.is_multipart_form_data()) {
      std::vector<Part> parts;
      if (!read_parts(reader, p->config.max_upload_bytes, parts, res)) return;
      if (!multipart_garment(parts, dir, section, res)) return;
    } else {
      json body;
      if (!read_json(req, reader, body, res)) return;
      for (const auto& [key, value] : body.items()) {
        if (key != "sample" && key != "size" && key != "body" && key != "material")
          return send_problem(
              res, 400, "/" + key,
              "unknown field '" + key + "' (sample, size, body with dress_form; upload files as multipart)");
        section[key] = value;
      }
      if (section.contains("body") && section["body"].is_object() && section["body"].contains("mesh"))
        return send_problem(res, 400, "/body/mesh", "a body mesh is uploaded as multipart part 'body'");
    }
    if (!section.contains("sample") && !section.contains("pattern"))
      return send_problem(res, 400, "", "give a sample and size, or upload a pattern file (multipart part 'pattern')");
    auto g = sew_studio_garment(id, dir, section, PackageLimits{}, geometry::CancelToken{});
    if (!g) return send_failure(res, g.error());
    // The garment a saved job prints on (finer mesh) starts sewing now, so a save need not wait.
    start_print_garment(**g, PackageLimits{});
    cleanup.keep = true;
    std::shared_ptr<StudioGarment> shared(std::move(*g));
    spdlog::info("printd: studio garment {} sewn in {:.1f} s ({} vertices)", id, shared->sew_seconds,
                 shared->sewn.garment.vertices_mm.size());
    const json reply = shared->describe();
    cache->put(std::move(shared));
    send_json(res, 201, reply);
  });

  im.server->Get(id_re, [cache](const httplib::Request& req, httplib::Response& res) {
    auto g = cache->get(req.matches[1]);
    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    send_json(res, 200, g->describe());
  });

  im.server->Delete(id_re, [cache](const httplib::Request& req, httplib::Response& res) {
    if (!cache->erase(req.matches[1])) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    res.status = 204;
  });

  im.server->Get(id_re + "/garment.obj", [cache](const httplib::Request& req, httplib::Response& res) {
    auto g = cache->get(req.matches[1]);
    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    res.set_content(g->obj, "text/plain; charset=utf-8");
  });

  im.server->Get(id_re + "/atlas.png", [cache](const httplib::Request& req, httplib::Response& res) {
    auto g = cache->get(req.matches[1]);
    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    std::ifstream in(g->dir / "garment" / "atlas.png", std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in) return send_error(res, 500, "atlas of garment " + g->id + " cannot be read");
    res.set_content(s.str(), "image/png");
  });

  im.server->Post(id_re + "/assets", [p, cache](const httplib::Request& req, httplib::Response& res,
                                                const httplib::ContentReader& reader) {
    auto g = cache->get(req.matches[1]);
    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    std::vector<Part> parts;
    if (req.is_multipart_form_data()) {
      if (!read_parts(reader, p->config.max_upload_bytes, parts, res)) return;
    } else {
      const std::string name = req.get_param_value("name");
      if (name.empty()) return send_problem(res, 400, "/name", "give the asset's file name (?name=motif.png)");
      parts.push_back({"file", name, {}});
      if (!read_body(req, reader, p->config.max_upload_bytes, parts.back().data, res)) return;
    }
    json paths = json::array();
    for (const Part& part : parts) {
      if (!plain_name(part.filename))
        return send_problem(res, 400, "/" + part.name,
                            "asset name '" + part.filename + "': use letters, digits, '-', '_' and '.' (not leading)");
      const std::string rel = "assets/" + part.filename;
      std::lock_guard lock(g->mu);
      if (!write_bytes(g->dir / rel, part.data)) return send_error(res, 500, rel + ": cannot store the upload");
      paths.push_back(rel);
    }
    send_json(res, 201, json{{"paths", paths}});
  });

  im.server->Post(id_re + "/preview",
                  [cache](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader) {
                    auto g = cache->get(req.matches[1]);
                    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
                    json body;
                    if (!read_json(req, reader, body, res)) return;
                    // The body is job.json's design object, or {"design": {...}}.
                    const json design = body.contains("design") ? body["design"] : body;
                    auto preview = render_studio_preview(*g, design, PackageLimits{}, geometry::CancelToken{});
                    if (!preview && preview.error().code == ErrorCode::kCancelled) {
                      // A newer design for this garment came in: the page drops this answer.
                      res.set_header("X-Preview-Superseded", "1");
                      return send_json(res, 409, json{{"error", preview.error().message}, {"superseded", true}});
                    }
                    if (!preview) return send_failure(res, preview.error());
                    res.set_header("X-Parse-Ms", std::to_string(preview->parse_ms));
                    res.set_header("X-Build-Ms", std::to_string(preview->build_ms));
                    res.set_header("X-Render-Ms", std::to_string(preview->render_ms));
                    res.set_header("X-Encode-Ms", std::to_string(preview->encode_ms));
                    res.set_header("Cache-Control", "no-store");
                    res.set_content(std::move(preview->png), "image/png");
                  });

  im.server->Post(id_re + "/job", [p, cache](const httplib::Request& req, httplib::Response& res,
                                             const httplib::ContentReader& reader) {
    auto g = cache->get(req.matches[1]);
    if (!g) return send_error(res, 404, "no studio garment " + std::string(req.matches[1]));
    json body;
    if (!read_json(req, reader, body, res)) return;
    for (const auto& [key, value] : body.items())
      if (key != "name" && key != "design" && key != "finishing" && key != "marker" && key != "print" &&
          key != "garment")
        return send_problem(res, 400, "/" + key,
                            "unknown field '" + key + "' (name, design, finishing, marker, print, garment)");
    if (body.contains("garment")) {
      if (!body["garment"].is_object())
        return send_problem(res, 400, "/garment", "garment must be an object (mesh_edge, drape)");
      for (const auto& [key, value] : body["garment"].items())
        if (key != "mesh_edge" && key != "drape")
          return send_problem(res, 400, "/garment/" + key,
                              "unknown field '" + key + "' (the saved garment's mesh_edge and drape)");
    }
    const fs::path zip = g->dir / ("job-" + std::to_string(p->upload_serial.fetch_add(1)) + ".zip");
    struct Cleanup {
      fs::path path;
      ~Cleanup() {
        std::error_code ec;
        fs::remove(path, ec);
      }
    } cleanup{zip};
    if (auto st = write_studio_package(*g, body, zip, PackageLimits{}); !st) return send_failure(res, st.error());
    std::ifstream in(zip, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in) return send_error(res, 500, zip.string() + ": cannot read the package");
    const std::string name = body.value("name", std::string("studio-design"));
    res.set_header("Content-Disposition",
                   "attachment; filename=\"" + (plain_name(name) ? name : "studio-design") + ".zip\"");
    res.set_content(s.str(), "application/zip");
  });

  // The page is a console asset (console_dir/studio/, served by the static routes with three.js at
  // /vendor/three/); a bare /studio goes to its folder.
  im.server->Get("/studio", [](const httplib::Request&, httplib::Response& res) {
    res.status = 302;
    res.set_header("Location", "/studio/");
  });
}

}  // namespace tp::host::http
