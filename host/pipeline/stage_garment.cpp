// host/pipeline/stage_garment.cpp: the garment stage: the pieces sewn on the job's body (or laid
// flat when it has none), aligned to the body first, the distortion figures and fit checks, the
// 3D garment as OBJ and its previews.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "geometry/body/load_body_obj.h"
#include "geometry/garment/align_to_body.h"
#include "geometry/garment/distortion.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/garment/flat_garment.h"
#include "geometry/garment/flat_pieces.h"
#include "geometry/garment/garment_obj.h"
#include "geometry/garment/initial_placement.h"
#include "geometry/pattern/import/load_pattern.h"
#include "geometry/samples/garments.h"
#include "geometry/sewing/drape_garment.h"
#include "geometry/sewing/sew_garment.h"
#include "host/pipeline/garment_checks.h"
#include "host/pipeline/garment_files.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_steps.h"
#include "host/pipeline/sewing_choice.h"

namespace tp::host::internal {

namespace {

Error from_geometry(const geometry::Error& e) {
  return Error{e.code == geometry::ErrorCode::kCancelled ? ErrorCode::kCancelled : ErrorCode::kPipeline, e.message};
}

// The job's body as a collision object: the dress form of its measurements or its mesh file.
Result<std::shared_ptr<const geometry::BodySdf>> job_body(const PipelineState& ps) {
  const GarmentSpec& g = ps.job.garment;
  if (g.body_kind == "mesh") {
    auto mesh = geometry::load_body_obj(g.body_mesh->string(), g.body_mesh_scale_to_mm);
    if (!mesh) return fail(from_geometry(mesh.error()));
    auto sdf = geometry::BodySdf::build(std::move(*mesh));
    if (!sdf) return fail(from_geometry(sdf.error()).with_context(g.body_mesh->string()));
    return std::make_shared<const geometry::BodySdf>(std::move(*sdf));
  }
  if (ps.measurements) {
    auto sdf = geometry::samples::make_dress_form_sdf(*ps.measurements);
    if (!sdf) return fail(from_geometry(sdf.error()).with_context("dress form"));
    return *sdf;
  }
  return std::shared_ptr<const geometry::BodySdf>();
}

// The job's fabric: its preset with the job's overrides.
Result<geometry::ClothMaterial> job_material(const GarmentMaterialSpec& spec) {
  auto m = geometry::cloth_material_preset(spec.preset);
  if (!m) return fail(from_geometry(m.error()).with_context("garment.material"));
  if (spec.density_g_m2) m->density_g_m2 = *spec.density_g_m2;
  if (spec.stretch_limit) m->stretch_limit = *spec.stretch_limit;
  if (spec.bending_rigidity_uN_m) m->bending_rigidity_uN_m = *spec.bending_rigidity_uN_m;
  if (spec.friction) m->friction = *spec.friction;
  if (auto ok = geometry::validate_cloth_material(*m); !ok) return fail(from_geometry(ok.error()).with_context("garment.material"));
  return *m;
}

// Whether the job's pattern file is a GarmentCode specification (named or detected).
bool garmentcode_pattern(const GarmentSpec& g) {
  if (!g.pattern || g.pattern_format == "garmentcode") return g.pattern.has_value();
  if (g.pattern_format != "auto") return false;
  std::ifstream in(*g.pattern, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto format = geometry::detect_pattern_format(g.pattern->filename().string(), text);
  return format && *format == geometry::PatternFormat::kGarmentCode;
}

// The sewing solver of a job: its `garment.sewing`, or the one "auto" picks (sewing_choice.h).
std::string sewing_solver(const GarmentSpec& g, const geometry::Pattern& pattern) {
  if (g.sewing != "auto") return g.sewing;
  return auto_sewing(pattern, garmentcode_pattern(g)).solver == geometry::SewSolver::kXpbd ? "xpbd" : "arap";
}

// The garment stage's progress: a solver's own fraction mapped into [from, to] of the stage,
// passed on only when it has moved by a percent or more (the solvers call once per iteration).
std::function<void(double)> garment_progress(PipelineState& ps, double from, double to, const char* what) {
  if (!ps.options.on_progress) return {};
  return [&ps, from, to, what, last = -1.0](double f) mutable {
    const double stage = from + (to - from) * std::clamp(f, 0.0, 1.0);
    if (stage - last < 0.01) return;
    last = stage;
    ps.options.on_progress(Stage::kGarment, stage,
                           std::string(what) + " " + std::to_string(std::lround(100 * f)) + " %");
  };
}

// Drapes the sewn garment in the job's fabric; its figures go into report.garment.drape.
Result<geometry::Garment> drape_job_garment(PipelineState& ps, const std::vector<int>& flat, nlohmann::json& figures) {
  auto material = job_material(ps.job.garment.material);
  if (!material) return fail(material.error());
  geometry::DrapeOptions o;
  o.material = *material;
  o.on_progress = garment_progress(ps, 0.5, 1.0, "draping");
  geometry::DrapeStats st;
  auto g = geometry::drape_garment(flat.empty() ? *ps.garment : geometry::garment_without(*ps.garment, flat), *ps.body,
                                   o, &st, &ps.cancel);
  if (!g) return fail(from_geometry(g.error()));
  figures = {{"material", material->name},
             {"density_g_m2", material->density_g_m2},
             {"stretch_limit", material->stretch_limit},
             {"bending_rigidity_uN_m", material->bending_rigidity_uN_m},
             {"friction", material->friction},
             {"substeps", st.substeps},
             {"simulated_s", st.simulated_s},
             {"max_speed_mm_s", st.max_speed_mm_s},
             {"self_intersections", geometry::count_self_intersections(*g)},
             {"body_crossings", geometry::count_body_crossings(*g, ps.body->mesh())},
             {"wall_s", st.seconds}};
  return std::move(*g);
}

}  // namespace

Status stage_garment(PipelineState& ps) {
  auto body = job_body(ps);
  if (!body) return fail(body.error());
  ps.body = *body;
  // On a body, pieces joined to no other piece (a pocket bag, a label) are printed flat.
  const std::vector<int> flat = ps.body && !ps.garment ? geometry::unjoined_pieces(ps.pattern) : std::vector<int>{};

  geometry::SewStats stats;
  nlohmann::json alignment, start;
  if (ps.plan_garment) {
    // The job's stored plan: never sewn twice (a resume or a reprint prints this garment), and
    // the stitch gaps measured when it was sewn come with it.
    if (auto st = load_plan_garment(ps, &stats.stitch_gap_mm); !st) return st;
    ps.stage_reused = true;
  } else if (!ps.garment && ps.body) {
    // Pieces no stitch joins to the rest are not sewn: the others are, and those lie where a flat
    // job lays them, so they get a flat job's print.
    geometry::PatternPart part = geometry::pattern_without(ps.pattern, *ps.meshes, flat);
    // A pattern placed around another body (or in a mirrored frame) is brought onto this one.
    auto al = geometry::align_to_body(part.pattern, *ps.body);
    if (!al) return fail(from_geometry(al.error()));
    if (al->moved)
      alignment = {{"moved", true},
                   {"turned", al->turned},
                   {"offset_mm", {al->offset_mm.x, al->offset_mm.y, al->offset_mm.z}},
                   {"garment_kind", al->garment_kind},
                   {"reason", al->reason}};
    geometry::SewOptions opt;
    opt.target_edge_mm = ps.job.garment.mesh_edge_mm;
    const std::string solver = sewing_solver(ps.job.garment, part.pattern);
    opt.solver = solver == "xpbd" ? geometry::SewSolver::kXpbd : geometry::SewSolver::kArap;
    opt.on_progress = garment_progress(ps, 0.0, ps.job.garment.drape ? 0.5 : 1.0, "sewing");
    // Where the pieces start (the solver places them the same way): inside the body as placed,
    // and after the push out of it.
    geometry::PushOutStats pushed;
    (void)geometry::initial_placement(part.pattern, part.meshes, *ps.body, geometry::kStartClearance_mm, &pushed);
    start = {{"vertices", pushed.vertices},
             {"inside_body_placed", pushed.inside_before},
             {"inside_body_pushed", pushed.inside_after},
             {"max_push_mm", pushed.max_push_mm}};
    auto g = geometry::sew_garment(part.pattern, part.meshes, *ps.body, opt, &stats, &ps.cancel);
    if (!g) return fail(from_geometry(g.error()));
    std::vector<std::vector<double>> gaps(ps.pattern.stitches.size());
    for (size_t k = 0; k < part.stitches.size() && k < stats.stitch_gap_mm.size(); ++k)
      gaps[static_cast<size_t>(part.stitches[k])] = std::move(stats.stitch_gap_mm[k]);
    stats.stitch_gap_mm = std::move(gaps);
    auto whole = geometry::garment_with_flat_pieces(ps.pattern, *ps.meshes, part, *g);
    if (!whole) return fail(from_geometry(whole.error()));
    ps.garment = std::move(*whole);
    ps.garment_is_3d = true;
    ps.report["sewing"] = {{"solver", solver},
                           {"solver_asked", ps.job.garment.sewing},
                           {"levels", stats.levels},
                           {"coarse_discarded", stats.coarse_discarded},
                           {"sewing_iterations", stats.sewing_iterations},
                           {"relax_iterations", stats.relax_iterations},
                           {"contacts", stats.contacts},
                           {"wall_s", stats.seconds}};
  } else if (!ps.garment) {
    auto g = geometry::flat_garment(ps.pattern, *ps.meshes);
    if (!g) return fail(from_geometry(g.error()));
    ps.garment = std::move(*g);
    ps.garment_is_3d = false;
  }
  // The job may make its design on the draped garment: then it is the one measured and checked.
  std::optional<geometry::Garment> draped;
  nlohmann::json drape_figures;
  if (ps.garment_is_3d && ps.body && ps.job.garment.drape) {
    auto g = drape_job_garment(ps, flat, drape_figures);
    if (!g) return fail(g.error());
    draped = std::move(*g);
    if (ps.job.garment.correspondence == "draped") {
      // The flat pieces keep their flat place (and print) in the draped correspondence too.
      ps.garment = geometry::with_pieces_from(*draped, *ps.garment, flat);
    }
  }
  // The 3D garment as worn: without the pieces printed flat.
  const geometry::Garment worn = flat.empty() ? *ps.garment : geometry::garment_without(*ps.garment, flat);
  geometry::DistortionReport d = geometry::measure_distortion(ps.pattern, worn, ps.body.get());
  ps.report["garment"] = {{"mode", ps.garment_is_3d ? "3d" : "flat"},
                          {"vertices", d.vertices},
                          {"triangles", d.triangles},
                          {"strain_mean", d.strain_mean},
                          {"strain_p95", d.strain_p95},
                          {"strain_max", d.strain_max},
                          {"area_change", d.area_change},
                          {"seam_len_diff_max", d.seam_len_diff_max},
                          {"seam_len_diff_max_plain", d.seam_len_diff_max_plain},
                          {"strain_p95_plain", d.strain_p95_plain},
                          {"strain_p95_eased", d.strain_p95_eased},
                          {"eased_area_fraction", d.eased_area_fraction},
                          {"inside_body", d.inside_body},
                          {"min_clearance_mm", ps.body ? nlohmann::json(d.min_clearance_mm) : nlohmann::json(nullptr)}};
  ps.report["garment"]["stitches"] = stitches_json(ps.pattern, ps.stitch_sources, stats.stitch_gap_mm);
  if (!alignment.is_null()) ps.report["garment"]["alignment"] = alignment;
  if (!start.is_null()) ps.report["garment"]["start"] = start;
  if (!flat.empty()) {
    nlohmann::json fp = nlohmann::json::array();
    for (int p : flat)
      fp.push_back({{"piece", ps.pattern.pieces[static_cast<size_t>(p)].name},
                    {"reason",
                     "no stitch joins it to another piece: printed flat with the print a job without a body "
                     "gives it, not part of the 3D garment or its checks"}});
    ps.report["garment"]["flat_pieces"] = fp;
  }
  if (draped) {
    drape_figures["correspondence"] = ps.job.garment.correspondence;
    ps.report["garment"]["drape"] = drape_figures;
  }
  if (!ps.garment_is_3d) {
    if (!ps.stage_reused)
      if (auto st = save_plan_garment(ps, stats.stitch_gap_mm); !st) return st;
    return {};
  }

  // The 3D garment with its per-piece texture coordinates, and the previews for the report.
  const auto& out = ps.options.out_dir;
  if (auto st = write_text_file(out / "garment.obj", geometry::garment_to_obj(ps.pattern, worn)); !st) return st;
  auto previews =
      write_garment_previews(out, "garment-", worn, ps.body ? &ps.body->mesh() : nullptr, rip::PngChannels::kRgba);
  if (!previews) return fail(previews.error());
  ps.report["garment"]["files"] = {{"obj", "garment.obj"}, {"previews", *previews}};
  if (draped) {
    // The garment as worn: the draped one's previews beside the sewn one's.
    if (auto st = write_text_file(out / "garment-draped.obj", geometry::garment_to_obj(ps.pattern, *draped)); !st) return st;
    auto dp = write_garment_previews(out, "garment-draped-", *draped, &ps.body->mesh(), rip::PngChannels::kRgba);
    if (!dp) return fail(dp.error());
    ps.report["garment"]["files"]["draped_obj"] = "garment-draped.obj";
    ps.report["garment"]["files"]["draped_previews"] = *dp;
  }

  // Fit checks on the final garment: a garment not sewn, tangled or off the body fails here.
  const geometry::FitLimits limits = fit_limits(ps.job.garment.checks);
  geometry::FitReport fit = geometry::check_fit(ps.pattern, *ps.garment, ps.body.get(), stats.stitch_gap_mm, limits);
  ps.report["garment"]["checks"] = checks_json(ps.pattern, fit, limits, "garment-");
  if (!fit.pass) return fail(ErrorCode::kPipeline, checks_failure_message(fit, "garment-"));
  // Only a garment that passed its checks becomes the job's plan.
  if (!ps.stage_reused)
    if (auto st = save_plan_garment(ps, stats.stitch_gap_mm); !st) return st;
  return {};
}

}  // namespace tp::host::internal
