// host/daemon/studio/studio_garment.cpp: sewing a studio garment through the pipeline's stages
// and writing the mesh the browser maps previews onto.
#include "host/daemon/studio/studio_garment.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <fstream>
#include <list>
#include <mutex>
#include <sstream>
#include <thread>

#include <spdlog/spdlog.h>

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
  // The fade of a planar layer at the garment's sides (its weight follows the surface's angle)
  // otherwise splits the render triangles there five times over (measured on simple_top: 81,773
  // render triangles with a planar layer, 16,729 with this), where the image rarely reaches.
  o.weight_tolerance = 8.0 / 255;
  // One change after another on the same garment: the base keeps what a design can share.
  o.keep_layer_data = true;
  return o;
}

geometry::CancelToken StudioGarment::begin_preview() {
  std::lock_guard lock(preview_mu_);
  preview_cancel_.cancel();
  preview_cancel_ = geometry::CancelToken{};
  return preview_cancel_;
}

StudioGarment::~StudioGarment() {
  if (print_sewing) {
    // A sewing still running stops at its next check and removes the folder itself when it ends.
    std::lock_guard lock(print_sewing->mu);
    print_sewing->cancel.cancel();
    if (!print_sewing->done) {
      print_sewing->orphaned = true;
      return;
    }
  }
  std::error_code ec;
  if (!dir.empty()) fs::remove_all(dir, ec);
}

namespace {

// The background sewings: their threads, owned here and joined (finished ones when the next begins,
// all of them by wait_for_print_sewings before printd exits, since they use the process's thread
// pool and logger, which static destruction takes down).
struct PrintSewings {
  struct Running {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> ended;  ///< set by the thread as its last step
  };
  std::mutex mu;
  std::list<Running> threads;
};
PrintSewings& print_sewings() {
  // Never destroyed: at exit a joinable std::thread's destructor would terminate the process.
  static PrintSewings* s = new PrintSewings;
  return *s;
}
// Joins the sewings that have ended and says how many still run. Call with s.mu held.
std::size_t reap_ended(PrintSewings& s) {
  for (auto it = s.threads.begin(); it != s.threads.end();) {
    if (it->ended->load()) {
      it->thread.join();  // it has set its flag, so it is returning
      it = s.threads.erase(it);
    } else {
      ++it;
    }
  }
  return s.threads.size();
}
constexpr int kPrintSewingsAtOnce = 2;
constexpr int kPrintSewingNice = 10;

}  // namespace

void start_print_garment(StudioGarment& g, const PackageLimits& limits) {
  json section = g.print_garment_section;
  section["drape"] = false;
  if (section == g.garment_section || g.print_sewing) return;
  PrintSewings& sewings = print_sewings();
  std::lock_guard sewings_lock(sewings.mu);
  if (reap_ended(sewings) >= kPrintSewingsAtOnce) return;
  auto job = parse_studio_job(g, studio_manifest(g, {{"garment", section}}, true), limits);
  if (!job) return;  // a save reports the same error when it sews
  auto state = std::make_shared<PrintGarmentSewing>();
  state->section = section;
  g.print_sewing = state;
  auto ended = std::make_shared<std::atomic<bool>>(false);
  std::thread thread([state, ended, job = std::move(*job), dir = g.dir, id = g.id] {
    // Nice applies per thread on Linux, and the sewing's worker threads inherit it.
    ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), kPrintSewingNice);
    const auto t0 = std::chrono::steady_clock::now();
    auto sewn = sew_job_garment(job, dir / "print-garment-bg", state->cancel);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bool orphaned = false;
    {
      std::lock_guard lock(state->mu);
      if (sewn)
        state->result = std::make_shared<const JobGarment>(std::move(*sewn));
      else
        state->result = fail(sewn.error().with_context("the garment the saved job prints on"));
      state->seconds = s;
      state->done = true;
      orphaned = state->orphaned;
    }
    state->done_cv.notify_all();
    if (orphaned) {
      std::error_code ec;
      fs::remove_all(dir, ec);
    } else {
      spdlog::info("printd: studio garment {}: the print garment sewn in the background in {:.1f} s", id, s);
    }
    ended->store(true);
  });
  sewings.threads.push_back({std::move(thread), std::move(ended)});
}

void wait_for_print_sewings() {
  PrintSewings& s = print_sewings();
  std::list<PrintSewings::Running> threads;
  {
    std::lock_guard lock(s.mu);
    threads.swap(s.threads);
  }
  for (auto& r : threads) r.thread.join();
}

Result<std::shared_ptr<const JobGarment>> await_print_garment(StudioGarment& g, const json& section) {
  if (!g.print_sewing || g.print_sewing->section != section) return std::shared_ptr<const JobGarment>{};
  std::unique_lock lock(g.print_sewing->mu);
  g.print_sewing->done_cv.wait(lock, [&] { return g.print_sewing->done; });
  return g.print_sewing->result;
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
  g->atlas_islands = files->islands;
  // Previews render at the atlas dpi: a base prepared for another dpi's accuracy is not theirs.
  if (g->atlas_dpi != kStudioPreviewDpi) g->preview_base.reset();
  return g;
}

}  // namespace tp::host
