// host/app/printctl/bench_garment_corpus.cpp: corpus folders: pattern files, sidecars and body rules.
#include "host/app/printctl/bench_garment_corpus.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "geometry/body/load_body_obj.h"
#include "geometry/pattern/import/freesewing_sizes.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"

namespace tp::host::cli {
namespace {

namespace fs = std::filesystem;

// An OBJ body without stated units spanning fewer units than this is in metres.
constexpr double kMetresIfUnder = 10;

using BodyPtr = std::shared_ptr<const geometry::BodySdf>;

// Bodies already built, by a key naming their source, so patterns share them.
class BodyCache {
 public:
  Result<BodyPtr> mesh(const fs::path& path, double mm_per_unit) {
    const std::string key = path.lexically_normal().string() + "@" + std::to_string(mm_per_unit);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    auto m = geometry::load_body_obj(path.string(), mm_per_unit > 0 ? mm_per_unit : 1);
    if (!m) return fail(ErrorCode::kIo, m.error().message);
    if (mm_per_unit <= 0) {
      geometry::Box3 b = geometry::bounds(*m);
      double extent = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
      if (extent < kMetresIfUnder)
        for (auto& v : m->vertices_mm) v = v * 1000.0;
    }
    auto sdf = geometry::BodySdf::build(std::move(*m));
    if (!sdf) return fail(ErrorCode::kIo, path.string() + ": " + sdf.error().message);
    return cache_[key] = std::make_shared<const geometry::BodySdf>(std::move(*sdf));
  }
  Result<BodyPtr> dress_form(const std::string& key, const geometry::BodyMeasurements& m) {
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    auto sdf = geometry::samples::make_dress_form_sdf(m);
    if (!sdf) return fail(ErrorCode::kIo, key + ": " + sdf.error().message);
    return cache_[key] = *sdf;
  }

 private:
  std::map<std::string, BodyPtr> cache_;
};

bool is_pattern_file(const fs::path& p) {
  const std::string n = p.filename().string();
  if (n.size() > 10 && n.compare(n.size() - 10, 10, ".body.json") == 0) return false;
  const std::string ext = p.extension().string();
  return ext == ".json" || ext == ".svg" || ext == ".dxf";
}

// The body a sidecar names, or an error naming the sidecar and its field.
Result<BodyPtr> sidecar_body(const fs::path& sidecar, BodyCache& cache, std::string& body_name) {
  std::ifstream in(sidecar);
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(ss.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail(ErrorCode::kValidation, sidecar.string() + ": not a JSON object");
  if (j.contains("mesh") && j["mesh"].is_string()) {
    double unit = -1;
    if (j.contains("units")) {
      const std::string u = j["units"].is_string() ? j["units"].get<std::string>() : "";
      unit = u == "mm" ? 1 : u == "cm" ? 10 : u == "m" ? 1000 : u == "in" ? 25.4 : 0;
      if (unit == 0) return fail(ErrorCode::kValidation, sidecar.string() + ": /units: mm, cm, m or in");
    }
    fs::path mesh = sidecar.parent_path() / j["mesh"].get<std::string>();
    body_name = mesh.string();
    return cache.mesh(mesh, unit);
  }
  if (j.contains("freesewing") && j["freesewing"].is_number_integer()) {
    auto m = geometry::freesewing_cis_female_adult(j["freesewing"].get<int>());
    if (!m) return fail(ErrorCode::kValidation, sidecar.string() + ": /freesewing: a cisFemaleAdult size 28, 30, ..., 46");
    body_name = "dress_form cisFemaleAdult" + std::to_string(j["freesewing"].get<int>());
    return cache.dress_form(body_name, *m);
  }
  if (j.contains("size") && j["size"].is_string()) {
    auto m = geometry::samples::parse_size(j["size"].get<std::string>());
    if (!m) return fail(ErrorCode::kValidation, sidecar.string() + ": /size: " + m.error().message);
    body_name = "dress_form " + j["size"].get<std::string>();
    return cache.dress_form(body_name, *m);
  }
  return fail(ErrorCode::kValidation, sidecar.string() + ": needs \"mesh\" (with \"units\"), \"freesewing\" or \"size\"");
}

}  // namespace

Result<std::vector<CorpusEntry>> corpus_entries(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> files, objs;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file()) continue;
    if (is_pattern_file(e.path())) files.push_back(e.path());
    if (e.path().extension() == ".obj") objs.push_back(e.path());
  }
  if (ec) return fail(ErrorCode::kIo, dir.string() + ": " + ec.message());
  std::sort(files.begin(), files.end());
  BodyCache cache;
  std::vector<CorpusEntry> out;
  for (const fs::path& f : files) {
    CorpusEntry e;
    e.name = f.stem().string();
    e.pattern = f;
    Result<BodyPtr> body = fail(ErrorCode::kValidation, "no body: give " + e.name +
                                                            ".body.json, or put one .obj body in the folder");
    const fs::path sidecar = f.parent_path() / (e.name + ".body.json");
    const fs::path gc_body = dir / ".." / "bodies" / "mean_female.obj";
    if (fs::exists(sidecar)) {
      body = sidecar_body(sidecar, cache, e.body_name);
    } else if (auto size = geometry::freesewing_size_in_name(e.name)) {
      auto m = geometry::freesewing_cis_female_adult(*size);
      e.body_name = "dress_form cisFemaleAdult" + std::to_string(*size);
      if (m) body = cache.dress_form(e.body_name, *m);
    } else if (objs.size() == 1) {
      e.body_name = objs.front().string();
      body = cache.mesh(objs.front(), -1);
    } else if (fs::exists(gc_body)) {
      e.body_name = gc_body.lexically_normal().string();
      body = cache.mesh(gc_body, 1000);
    }
    if (body) e.body = *body;
    else e.error = body.error().message;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace tp::host::cli
