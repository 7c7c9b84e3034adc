// host/daemon/studio/studio_garment.cpp: sewing a studio garment through the pipeline's stages
// and writing the mesh the browser maps previews onto.
#include "host/daemon/studio/studio_garment.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

#include "host/common/text.h"
#include "host/job/manifest.h"
#include "host/pipeline/garment_files.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

geometry::RenderOptions studio_render_options(double dpi) {
  geometry::RenderOptions o;
  o.tolerance_mm = 25.4 / std::max(dpi, 1.0) / 4;
  o.min_triangle_mm = std::max(o.min_triangle_mm, o.tolerance_mm);
  // Occlusion resolved to half a preview pixel, not to 0.5 mm.
  o.occlusion_cell_mm = std::max(o.occlusion_cell_mm, 25.4 / std::max(dpi, 1.0) / 2);
  return o;
}

StudioGarment::~StudioGarment() {
  std::error_code ec;
  if (!dir.empty()) fs::remove_all(dir, ec);
}

json StudioGarment::describe() const {
  json pieces = json::array();
  for (size_t i = 0; i < sewn.pattern.pieces.size(); ++i)
    pieces.push_back({{"index", i}, {"name", sewn.pattern.pieces[i].name}});
  const std::string base = "/api/v1/studio/garments/" + id;
  return {{"id", id},
          {"garment", garment_section},
          {"mode", sewn.is_3d ? "3d" : "flat"},
          {"pieces", pieces},
          {"vertices", sewn.garment.vertices_mm.size()},
          {"sew_s", sew_seconds},
          {"atlas", {{"width_px", atlas_width_px}, {"height_px", atlas_height_px}, {"dpi", atlas_dpi}}},
          {"urls",
           {{"mesh", base + "/garment.obj"},
            {"atlas", base + "/atlas.png"},
            {"preview", base + "/preview"},
            {"assets", base + "/assets"},
            {"job", base + "/job"}}}};
}

std::string studio_manifest(const StudioGarment& g, const json& rest, bool for_print) {
  json j = {{"format", "tp-job/1"},
            {"name", "studio-design"},
            {"garment", for_print ? g.print_garment_section : g.garment_section}};
  j["marker"] = {{"fabric_width", "1.6 m"}};
  if (rest.is_object())
    for (const auto& [key, value] : rest.items()) j[key] = value;
  return dump_json(j, 2) + "\n";
}

Result<Job> parse_studio_job(const StudioGarment& g, const std::string& manifest, const PackageLimits& limits) {
  // The session folder is the package: its job.json is the manifest being checked.
  {
    std::ofstream out(g.dir / "job.json", std::ios::binary | std::ios::trunc);
    out << manifest;
    if (!out) return fail(ErrorCode::kIo, (g.dir / "job.json").string() + ": cannot write");
  }
  auto package = JobPackage::open(g.dir, {}, limits);
  if (!package) return fail(package.error());
  return parse_job(manifest, &*package);
}

Result<std::unique_ptr<StudioGarment>> sew_studio_garment(std::string id, const fs::path& dir, json garment_section,
                                                          const PackageLimits& limits,
                                                          const geometry::CancelToken& cancel) {
  auto g = std::make_unique<StudioGarment>();
  g->id = std::move(id);
  g->dir = dir;
  g->print_garment_section = garment_section;
  // A preview vertex count, and the garment as sewn (draping only changes how it hangs, and
  // the design is made on the sewn one).
  if (!garment_section.contains("mesh_edge")) garment_section["mesh_edge"] = kStudioMeshEdge;
  if (!garment_section.contains("drape")) garment_section["drape"] = false;
  g->garment_section = std::move(garment_section);
  auto job = parse_studio_job(*g, studio_manifest(*g, json::object()), limits);
  if (!job) return fail(job.error());
  const auto t0 = std::chrono::steady_clock::now();
  auto sewn = sew_job_garment(*job, dir / "garment", cancel);
  if (!sewn) return fail(sewn.error());
  g->sewn = std::move(*sewn);
  g->sew_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The blank atlas fixes the layout every preview repeats (same pieces, outlines and dpi).
  auto blank = make_job_renderer(*job, g->sewn, studio_render_options(kStudioPreviewDpi), cancel, &g->preview_base);
  if (!blank) return fail(blank.error());
  auto files =
      write_textured_garment(dir / "garment", "atlas", g->sewn.pattern, g->sewn.garment, **blank, kStudioPreviewDpi);
  if (!files) return fail(files.error());
  std::ifstream in(dir / "garment" / files->obj, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) return fail(ErrorCode::kIo, (dir / "garment" / files->obj).string() + ": cannot read");
  g->obj = text.str();
  g->atlas_width_px = files->texture_width_px;
  g->atlas_height_px = files->texture_height_px;
  g->atlas_dpi = files->texture_dpi;
  // Previews render at the atlas dpi: a base prepared for another dpi's accuracy is not theirs.
  if (g->atlas_dpi != kStudioPreviewDpi) g->preview_base.reset();
  return g;
}

}  // namespace tp::host
