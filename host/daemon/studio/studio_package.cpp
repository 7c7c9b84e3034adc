// host/daemon/studio/studio_package.cpp: zipping a studio job (libzip) and validating the zip.
#include "host/daemon/studio/studio_package.h"

#include <zip.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>

#include "host/job/manifest.h"

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
