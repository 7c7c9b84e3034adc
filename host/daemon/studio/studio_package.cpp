// host/daemon/studio/studio_package.cpp: zipping a studio job (libzip) and validating the zip.
#include "host/daemon/studio/studio_package.h"

#include <zip.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "geometry/design/transfer_surface_points.h"
#include "host/job/manifest.h"
#include "host/pipeline/job_garment.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};

// Adds `bytes` as entry `name` (deflated); the buffer must live until the archive is closed.
Status add_entry(zip_t* z, const std::string& name, const std::string& bytes, const fs::path& zip_path) {
  zip_source_t* src = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
  if (!src) return fail(ErrorCode::kIo, zip_path.string() + ": " + name + ": " + zip_strerror(z));
  const zip_int64_t idx = zip_file_add(z, name.c_str(), src, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8);
  if (idx < 0) {
    zip_source_free(src);
    return fail(ErrorCode::kIo, zip_path.string() + ": " + name + ": " + zip_strerror(z));
  }
  zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(idx), 0, ZIP_OPSYS_UNIX, (0100644u) << 16);
  return {};
}

Result<std::string> read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) return fail(ErrorCode::kIo, p.string() + ": cannot read");
  return s.str();
}

// Stroke points were painted on the preview garment (25 mm mesh); the garment a saved job prints
// on is sewn at another mesh edge and lies up to a few mm away, so every point moves to the same
// place of the fabric on it (a design is made on the sewn garment, so it is sewn undraped here).
Status move_strokes_to_print_garment(StudioGarment& g, const json& print_section, json& design,
                                     const PackageLimits& limits) {
  if (!design.is_object() || !design.contains("layers") || !design["layers"].is_array()) return {};
  auto is_stroke = [](const json& l) {
    return l.is_object() && l.value("type", "") == "stroke" && l.contains("points") && l["points"].is_array();
  };
  if (std::none_of(design["layers"].begin(), design["layers"].end(), is_stroke)) return {};
  json section = print_section;
  section["drape"] = false;
  if (section == g.garment_section) return {};
  if (!g.print_sewn || g.print_sewn_section != section) {
    // Sewn in the background since the garment was chosen, when it was this section.
    auto ready = await_print_garment(g, section);
    if (!ready) return fail(ready.error());
    if (*ready) {
      g.print_sewn = *ready;
      g.print_sewn_section = section;
    }
  }
  if (!g.print_sewn || g.print_sewn_section != section) {
    auto job = parse_studio_job(g, studio_manifest(g, {{"garment", section}}, true), limits);
    if (!job) return fail(job.error());
    auto sewn = sew_job_garment(*job, g.dir / "print-garment", geometry::CancelToken{});
    if (!sewn) return fail(sewn.error().with_context("the garment the saved job prints on"));
    g.print_sewn = std::make_shared<const JobGarment>(std::move(*sewn));
    g.print_sewn_section = section;
  }
  for (json& layer : design["layers"]) {
    if (!is_stroke(layer)) continue;
    std::vector<geometry::Vec3> points;
    for (const json& p : layer["points"]) {
      if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
        return {};  // the validator names a malformed point
      points.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
    }
    auto moved = geometry::transfer_surface_points(g.sewn.pattern, g.sewn.garment, g.print_sewn->garment, points);
    if (!moved) return fail(ErrorCode::kPipeline, "stroke '" + layer.value("name", "") + "': " + moved.error().message);
    json out = json::array();
    for (const geometry::Vec3& q : *moved)
      out.push_back({std::round(q.x * 1000) / 1000, std::round(q.y * 1000) / 1000, std::round(q.z * 1000) / 1000});
    layer["points"] = out;
  }
  return {};
}

}  // namespace

Status write_studio_package(StudioGarment& g, const json& settings, const fs::path& zip_path,
                            const PackageLimits& limits) {
  std::lock_guard lock(g.mu);
  json rest = json::object();
  for (const char* key : {"name", "design", "finishing", "marker", "print"})
    if (settings.contains(key)) rest[key] = settings[key];
  // The garment prints with the product's normal mesh and drape unless the designer chose them
  // (the preview's coarse, undraped garment is only for the studio).
  json garment = g.print_garment_section;
  if (settings.contains("garment") && settings["garment"].is_object())
    for (const auto& [key, value] : settings["garment"].items()) garment[key] = value;
  rest["garment"] = garment;
  if (rest.contains("design"))
    if (auto st = move_strokes_to_print_garment(g, garment, rest["design"], limits); !st) return st;
  if (rest.contains("marker") && rest["marker"].is_object() && !rest["marker"].contains("fabric_width"))
    rest["marker"]["fabric_width"] = "1.6 m";
  const std::string manifest = studio_manifest(g, rest, true);
  if (auto job = parse_studio_job(g, manifest, limits); !job) return fail(job.error());

  // job.json and every upload, in name order (a deterministic archive for the same session).
  std::vector<std::pair<std::string, std::string>> entries;
  entries.emplace_back("job.json", manifest);
  std::vector<fs::path> assets;
  std::error_code ec;
  if (fs::is_directory(g.dir / "assets", ec))
    for (const auto& e : fs::directory_iterator(g.dir / "assets", ec))
      if (e.is_regular_file()) assets.push_back(e.path());
  std::sort(assets.begin(), assets.end());
  for (const fs::path& p : assets) {
    auto bytes = read_file(p);
    if (!bytes) return fail(bytes.error());
    entries.emplace_back("assets/" + p.filename().string(), std::move(*bytes));
  }
  int err = 0;
  fs::remove(zip_path, ec);
  std::unique_ptr<zip_t, ZipCloser> z(zip_open(zip_path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err));
  if (!z)
    return fail(ErrorCode::kIo,
                zip_path.string() + ": cannot create the archive (libzip error " + std::to_string(err) + ")");
  for (const auto& [name, bytes] : entries)
    if (auto st = add_entry(z.get(), name, bytes, zip_path); !st) return st;
  if (zip_close(z.get()) != 0) return fail(ErrorCode::kIo, zip_path.string() + ": " + zip_strerror(z.get()));
  z.release();

  // The archive as a reader gets it: unpacked under the limits and validated.
  const fs::path check = zip_path.parent_path() / (zip_path.stem().string() + ".check");
  fs::remove_all(check, ec);
  auto package = JobPackage::open(zip_path, check, limits);
  Status result = {};
  if (!package)
    result = fail(package.error().with_context("saved package"));
  else if (auto job = load_job(*package); !job)
    result = fail(job.error().with_context("saved package"));
  fs::remove_all(check, ec);
  return result;
}

}  // namespace tp::host
