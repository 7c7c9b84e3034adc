// host/app/printctl/cmd_bench_garment.cpp: `printctl bench garment`: builds garments at a given vertex
// count (samples, one pattern, or every pattern of a corpus folder) and prints their distortion,
// fit-check figures and build time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/body/load_body_obj.h"
#include "geometry/garment/align_to_body.h"
#include "geometry/garment/distortion.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/garment/flat_pieces.h"
#include "geometry/garment/initial_placement.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/import/garmentcode.h"
#include "geometry/pattern/import/load_pattern.h"
#include "geometry/pattern/pattern_json.h"
#include "geometry/pattern/suggest_stitches.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "geometry/sewing/drape_garment.h"
#include "geometry/sewing/sew_garment.h"
#include "host/app/printctl/bench_garment_corpus.h"
#include "host/app/printctl/commands.h"
#include "host/pipeline/garment_checks.h"
#include "host/pipeline/garment_files.h"
#include "host/pipeline/sewing_choice.h"

namespace tp::host::cli {
namespace {

struct BenchGarmentArgs {
  std::string garment;
  std::string pattern;
  std::string body;
  double body_mm_per_unit = 1000;
  std::string size = "M";
  int vertices = 10000;
  int threads = 2;
  std::string data;
  std::string out;  ///< when set: each garment's OBJ and previews go here
  std::vector<std::string> corpus;  ///< folders whose every pattern is benched on its body
  double min_score = geometry::SuggestOptions{}.min_score;  ///< suggestions for patterns without stitches
  geometry::SewOptions sew;  ///< solver settings other than mesh size and threads
  bool solver_auto = true;   ///< no --solver: the one a job's garment.sewing "auto" picks
  geometry::FitLimits limits;
  std::string material = "cotton-poplin";  ///< drape fabric preset
  bool drape = true;
};

// Share of the stitched length (longer sides) on stitches whose sides differ by more than 1 %:
// the eased and gathered seams, sewn with the longer side distributed along the shorter.
double gathered_fraction(const geometry::DistortionReport& r) {
  double all = 0, eased = 0;
  for (const auto& sl : r.seams) {
    const double longer = std::max(sl.a_mm, sl.b_mm);
    all += longer;
    if (std::abs(sl.a_mm - sl.b_mm) > 0.01 * longer) eased += longer;
  }
  return all > 0 ? eased / all : 0;
}

/// Pass/fail tallies of a run, for the corpus summary.
struct Tally {
  int patterns = 0, pass = 0, fail = 0, errors = 0;
};

[[noreturn]] void die(const std::string& msg, int code) {
  std::fprintf(stderr, "printctl bench garment: %s\n", msg.c_str());
  throw CLI::RuntimeError(code);
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One line per stitch: its pieces and edges, 2D lengths of both sides and the sewn length.
std::string seam_lines(const geometry::Pattern& pattern, const geometry::DistortionReport& r) {
  auto side = [&](const geometry::EdgeSpan& e) {
    const geometry::Piece& p = pattern.pieces[static_cast<size_t>(e.piece)];
    return p.name + "." + p.edges[static_cast<size_t>(e.edge)].name;
  };
  std::string out;
  for (const auto& sl : r.seams) {
    const geometry::Stitch& st = pattern.stitches[static_cast<size_t>(sl.stitch)];
    char nums[192];
    std::snprintf(nums, sizeof nums, " a_mm=%.2f b_mm=%.2f sewn_mm=%.2f diff=%.4f ease=%.3f\n", sl.a_mm, sl.b_mm,
                  sl.sewn_mm, sl.diff, st.ease_ratio);
    out += std::to_string(sl.stitch) + " " + side(st.a) + " " + side(st.b) + nums;
  }
  return out;
}

// Meshes `pattern` for about `vertices` vertices, sews it on `body` and prints one line. A pattern
// without stitches gets the suggested ones; one placed around another body is aligned first.
// Failures of one pattern print `error=` and count, so a corpus run goes on.
void bench_one(const std::string& name, geometry::Pattern pattern, const geometry::BodySdf& body,
               const BenchGarmentArgs& a, Tally& tally, bool garmentcode) {
  ++tally.patterns;
  auto error_line = [&](const std::string& why) {
    ++tally.errors;
    std::printf("garment=%s checks=error error=\"%s\"\n", name.c_str(), why.c_str());
    std::fflush(stdout);
  };
  int suggested = 0;
  if (pattern.stitches.empty()) {
    geometry::SuggestOptions so;
    so.min_score = a.min_score;
    suggested = geometry::accept_suggestions(pattern, geometry::suggest_stitches(pattern, so), a.min_score);
  }
  if (pattern.stitches.empty()) return error_line("no stitches (none in the pattern, none suggested)");
  bool aligned = false;
  // As the pipeline: pieces no stitch joins are left out of the garment (printed flat).
  const std::vector<int> flat = geometry::unjoined_pieces(pattern);
  const auto t0 = std::chrono::steady_clock::now();
  geometry::SewOptions o = a.sew;
  if (a.solver_auto) {
    // As a job with garment.sewing "auto" sews this pattern.
    const SewingChoice choice = auto_sewing(pattern, garmentcode);
    o.solver = choice.solver;
  }
  o.target_edge_mm = geometry::target_edge_for_vertex_count(pattern, a.vertices);
  o.threads = a.threads;
  geometry::SewStats stats;
  std::optional<geometry::Garment> g;
  if (flat.empty()) {
    auto al = geometry::align_to_body(pattern, body);
    if (!al) return error_line(al.error().message);
    aligned = al->moved;
    auto sewn = geometry::sew_garment(pattern, body, o, &stats);
    if (!sewn) return error_line(sewn.error().what());
    g = std::move(*sewn);
  } else {
    geometry::TriangulateOptions to;
    to.target_edge_mm = o.target_edge_mm;
    auto meshes = geometry::mesh_pattern(pattern, to);
    if (!meshes) return error_line(meshes.error().what());
    geometry::PatternPart part = geometry::pattern_without(pattern, *meshes, flat);
    auto al = geometry::align_to_body(part.pattern, body);
    if (!al) return error_line(al.error().message);
    aligned = al->moved;
    auto sewn = geometry::sew_garment(part.pattern, part.meshes, body, o, &stats);
    if (!sewn) return error_line(sewn.error().what());
    std::vector<std::vector<double>> gaps(pattern.stitches.size());
    for (size_t k = 0; k < part.stitches.size() && k < stats.stitch_gap_mm.size(); ++k)
      gaps[static_cast<size_t>(part.stitches[k])] = std::move(stats.stitch_gap_mm[k]);
    stats.stitch_gap_mm = std::move(gaps);
    auto whole = geometry::garment_with_flat_pieces(pattern, *meshes, part, *sewn);
    if (!whole) return error_line(whole.error().what());
    // The figures, files and drape are of the 3D garment, without the flat pieces.
    g = geometry::garment_without(*whole, flat);
  }
  const double seconds = since(t0);
  // Where the pieces started: vertices inside the body as placed, and after the push out of it.
  geometry::PushOutStats start;
  {
    geometry::TriangulateOptions to;
    to.target_edge_mm = o.target_edge_mm;
    auto meshes = geometry::mesh_pattern(pattern, to);
    if (!meshes) return error_line(meshes.error().what());
    geometry::PatternPart part = geometry::pattern_without(pattern, *meshes, flat);
    (void)geometry::initial_placement(part.pattern, part.meshes, body, geometry::kStartClearance_mm, &start);
  }
  geometry::DistortionReport r = geometry::measure_distortion(pattern, *g, &body);
  geometry::FitReport fit = geometry::check_fit(pattern, *g, &body, stats.stitch_gap_mm, a.limits);
  if (!a.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (ec) die(a.out + ": " + ec.message(), 1);
    if (auto st = write_garment_files(a.out, name, pattern, *g, body.mesh(), name + "_body"); !st) die(st.error().what(), 1);
    if (auto st = write_text_file(std::filesystem::path(a.out) / (name + "_seams.txt"), seam_lines(pattern, r)); !st)
      die(st.error().what(), 1);
  }
  // The drape in the bench's fabric: its time and whether it stayed untangled and outside the body.
  double drape_seconds = 0;
  int drape_self = -1, drape_inside = -1, drape_crossings = -1;
  double drape_strain_p95 = -1, drape_strain_p95_plain = -1, drape_simulated_s = 0, drape_seam_plain = -1;
  double drape_min_clearance_mm = 0;
  bool drape_settled = false;
  if (a.drape) {
    geometry::DrapeOptions d;
    auto m = geometry::cloth_material_preset(a.material);
    if (!m) die(m.error().message, 2);
    d.material = *m;
    d.threads = a.threads;
    d.clearance_mm = a.sew.clearance_mm;
    geometry::DrapeStats ds;
    auto dg = geometry::drape_garment(*g, body, d, &ds);
    if (!dg) return error_line(dg.error().what());
    drape_seconds = ds.seconds;
    drape_simulated_s = ds.simulated_s;
    drape_settled = ds.settled;
    drape_self = geometry::count_self_intersections(*dg);
    drape_crossings = geometry::count_body_crossings(*dg, body.mesh());
    const geometry::DistortionReport dr = geometry::measure_distortion(pattern, *dg, &body);
    drape_inside = dr.inside_body;
    drape_strain_p95 = dr.strain_p95;
    drape_strain_p95_plain = dr.strain_p95_plain;
    drape_seam_plain = dr.seam_len_diff_max_plain;
    drape_min_clearance_mm = dr.min_clearance_mm;
    if (!a.out.empty()) {
      if (auto st = write_garment_files(a.out, name + "_draped", pattern, *dg, body.mesh(), name + "_body"); !st)
        die(st.error().what(), 1);
      if (auto st =
              write_text_file(std::filesystem::path(a.out) / (name + "_draped_seams.txt"), seam_lines(pattern, dr));
          !st)
        die(st.error().what(), 1);
    }
  }
  (fit.pass ? tally.pass : tally.fail)++;
  std::string failed;
  for (const auto& f : fit.failures) failed += (failed.empty() ? "" : ",") + f.check;
  std::printf(
      "garment=%s solver=%s levels=%d coarse_edge_mm=%.1f coarse_discarded=%d coarse_fallback_gap_mm=%.2f "
      "coarse_fallback_self_intersections=%d mesh_edge_mm=%.1f vertices=%d stitches=%zu suggested=%d "
      "stitch_gap_max_mm=%.2f "
      "stitch_gap_p95_mm=%.2f "
      "self_intersections=%d inside_body=%d body_crossings=%d min_clearance_mm=%.1f body_distance_p50_mm=%.1f "
      "body_distance_p95_mm=%.1f "
      "off_body=%.4f "
      "unsewn=%zu start_inside=%d start_inside_pushed=%d start_max_push_mm=%.1f "
      "strain_mean=%.4f strain_p95=%.4f seam_len_diff_max=%.4f aligned=%s seconds=%.2f drape_seconds=%.2f "
      "drape_self_intersections=%d drape_inside_body=%d drape_body_crossings=%d drape_min_clearance_mm=%.1f "
      "drape_strain_p95=%.4f "
      "drape_simulated_s=%.3f "
      "drape_settled=%s gathered_fraction=%.3f strain_p95_plain=%.4f strain_p95_eased=%.4f eased_area=%.3f "
      "seam_len_diff_max_plain=%.4f drape_strain_p95_plain=%.4f drape_seam_len_diff_max_plain=%.4f checks=%s%s%s\n",
      name.c_str(), o.solver == geometry::SewSolver::kXpbd ? "xpbd" : "arap", stats.levels, stats.coarse_edge_mm,
      stats.coarse_discarded, stats.coarse_fallback_gap_mm, stats.coarse_fallback_self_intersections, o.target_edge_mm,
      r.vertices, pattern.stitches.size(), suggested, fit.stitch_gap_max_mm, fit.stitch_gap_p95_mm,
      fit.self_intersections, fit.inside_body, fit.body_crossings, r.min_clearance_mm, fit.body_distance_p50_mm,
      fit.body_distance_p95_mm, fit.off_body, fit.unsewn_pieces.size(), start.inside_before, start.inside_after,
      start.max_push_mm, r.strain_mean, r.strain_p95, r.seam_len_diff_max, aligned ? "yes" : "no", seconds,
      drape_seconds, drape_self, drape_inside, drape_crossings, drape_min_clearance_mm, drape_strain_p95,
      drape_simulated_s,
      !a.drape        ? "off"
      : drape_settled ? "yes"
                      : "no",
      gathered_fraction(r), r.strain_p95_plain, r.strain_p95_eased, r.eased_area_fraction, r.seam_len_diff_max_plain,
      drape_strain_p95_plain, drape_seam_plain, fit.pass ? "pass" : "fail",
      failed.empty() ? "" : " failed=", failed.c_str());
  for (const auto& f : fit.failures) std::printf("  %s: %s (look at %s_%s.png)\n", f.check.c_str(), f.message.c_str(), name.c_str(), f.view.c_str());
  std::fflush(stdout);
}

// Whether the pattern file is a GarmentCode specification (by its content, as jobs detect it).
bool is_garmentcode_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto format = geometry::detect_pattern_format(path.filename().string(), text);
  return format && *format == geometry::PatternFormat::kGarmentCode;
}

geometry::Pattern load_pattern(const std::string& path) {
  auto p = geometry::load_pattern(path);
  if (!p) die(p.error().what(), 2);
  return std::move(*p);
}

std::shared_ptr<const geometry::BodySdf> load_body(const std::string& path, double mm_per_unit) {
  auto mesh = geometry::load_body_obj(path, mm_per_unit);
  if (!mesh) die(mesh.error().what(), 2);
  auto sdf = geometry::BodySdf::build(std::move(*mesh));
  if (!sdf) die(sdf.error().what(), 2);
  return std::make_shared<const geometry::BodySdf>(std::move(*sdf));
}

void run_corpus(const BenchGarmentArgs& a) {
  for (const std::string& dir : a.corpus) {
    auto entries = corpus_entries(dir);
    if (!entries) die(entries.error().message, 2);
    Tally tally;
    for (const CorpusEntry& e : *entries) {
      if (!e.error.empty()) {
        ++tally.patterns;
        ++tally.errors;
        std::printf("garment=%s checks=error error=\"%s\"\n", e.name.c_str(), e.error.c_str());
        continue;
      }
      auto p = geometry::load_pattern(e.pattern);
      if (!p) {
        ++tally.patterns;
        ++tally.errors;
        std::printf("garment=%s checks=error error=\"%s\"\n", e.name.c_str(), p.error().what().c_str());
        continue;
      }
      bench_one(e.name, std::move(*p), *e.body, a, tally, is_garmentcode_file(e.pattern));
    }
    std::printf("corpus=%s patterns=%d pass=%d fail=%d errors=%d\n", dir.c_str(), tally.patterns, tally.pass, tally.fail,
                tally.errors);
    std::fflush(stdout);
  }
}

void run_bench_garment(const BenchGarmentArgs& a) {
  Tally tally;
  if (!a.corpus.empty()) return run_corpus(a);
  if (!a.pattern.empty()) {
    if (a.body.empty()) die("--pattern needs --body", 2);
    auto body = load_body(a.body, a.body_mm_per_unit);
    bench_one(std::filesystem::path(a.pattern).stem().string(), load_pattern(a.pattern), *body, a, tally,
              is_garmentcode_file(a.pattern));
    return;
  }
  auto m = geometry::samples::parse_size(a.size);
  if (!m) die(m.error().what(), 2);
  std::vector<std::string> names = a.garment.empty() ? geometry::samples::garment_names() : std::vector<std::string>{a.garment};
  auto body = geometry::samples::make_dress_form_sdf(*m);
  if (!body) die(body.error().what(), 1);
  for (const std::string& name : names) {
    auto p = geometry::samples::draft_garment(name, *m, a.size);
    if (!p) die(p.error().what(), 2);
    bench_one(name, std::move(*p), **body, a, tally, false);
  }
  if (!a.garment.empty() || a.data.empty()) return;
  // The GarmentCode references on their average female body (reference data: only when asked).
  std::filesystem::path data = a.data;
  auto mean_female = load_body((data / "garmentcode/bodies/mean_female.obj").string(), 1000);
  for (const char* spec : {"dress_pencil", "shirt_mean"}) {
    auto path = data / "garmentcode/patterns" / (std::string(spec) + "_specification.json");
    auto p = geometry::load_garmentcode(path);
    if (!p) die(p.error().what(), 2);
    bench_one(spec, std::move(*p), *mean_female, a, tally, true);
  }
}

}  // namespace

void register_bench_garment(CLI::App& bench) {
  auto args = std::make_shared<BenchGarmentArgs>();
  CLI::App* cmd = bench.add_subcommand("garment", "Sew garments at a vertex count; print strain, seam and body figures");
  cmd->add_option("--garment", args->garment, "one sample garment (default: all four, then GarmentCode references)");
  cmd->add_option("--pattern", args->pattern, "a pattern file (native JSON or GarmentCode specification)");
  cmd->add_option("--body", args->body, "body OBJ for --pattern");
  cmd->add_option("--body-units", args->body_mm_per_unit, "mm per OBJ unit (1000: metres)");
  cmd->add_option("--size", args->size, "dress form size for the samples");
  cmd->add_option("--vertices", args->vertices, "target garment vertex count")->check(CLI::Range(100, 1000000));
  cmd->add_option("--threads", args->threads, "threads for sewing")->check(CLI::Range(1, 8));
  cmd->add_option("--coarse-factor", args->sew.coarse_factor, "sew first on a mesh this much coarser (0: one level)")
      ->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--sewing-iterations", args->sew.sewing_iterations, "phase A iterations")->check(CLI::Range(4, 100000));
  cmd->add_option("--relax-iterations", args->sew.relax_iterations, "phase B iteration limit")->check(CLI::Range(1, 100000));
  cmd->add_option("--clearance-mm", args->sew.clearance_mm,
                  "distance the garment keeps from the body (sewing and drape; in the drape plain seams may draw their "
                  "vertices into it)")
      ->check(CLI::Range(0.0, 50.0));
  cmd->add_option("--seam-edge-weight", args->sew.seam_edge_weight, "stiffness of sewn seams against their pattern length")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--gravity", args->sew.gravity_per_mm, "weight per area relative to membrane stiffness")
      ->check(CLI::Range(0.0, 1.0));
  CLI::Option* solver =
      cmd->add_option(
             "--solver", args->sew.solver,
             "sewing solver: arap (springs) or xpbd (cloth with self-collision); default: what a job's garment.sewing "
             "\"auto\" picks for each pattern (docs/job-format.md)")
          ->transform(CLI::CheckedTransformer(std::map<std::string, geometry::SewSolver>{
              {"arap", geometry::SewSolver::kArap}, {"xpbd", geometry::SewSolver::kXpbd}}));
  cmd->add_option("--xpbd-close-speed", args->sew.xpbd_close_mm_s, "XPBD sewing: seam closing speed (mm/s)")
      ->check(CLI::Range(1.0, 10000.0));
  cmd->add_option("--xpbd-duration", args->sew.xpbd_duration_s, "XPBD sewing: simulated time limit (s)")
      ->check(CLI::Range(0.01, 100.0));
  cmd->add_option("--xpbd-stall", args->sew.xpbd_stall_s,
                  "XPBD sewing: stop once the widest seam gap stalls this long (s)")
      ->check(CLI::Range(0.01, 100.0));
  cmd->add_option("--corpus", args->corpus, "bench every pattern of this folder on its body (sidecar <stem>.body.json "
                                            "or the rules in docs/garments.md); repeatable")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--min-score", args->min_score, "suggested stitches for patterns without any: minimum score")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-stitch-gap-mm", args->limits.max_stitch_gap_mm, "fit check: stitch gap limit")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--max-self-intersections", args->limits.max_self_intersections,
                  "fit check: intersecting triangle pairs per triangle")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-inside-body", args->limits.max_inside_body, "fit check: fraction of vertices inside the body")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-body-crossings", args->limits.max_body_crossings,
                  "fit check: fraction of triangles crossing the body's surface")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-off-body", args->limits.max_off_body, "fit check: area fraction over 150 mm from the body")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--material", args->material, "drape fabric preset (jersey, cotton-poplin, silk-satin, denim)");
  cmd->add_flag("!--no-drape", args->drape, "skip the drape after sewing");
  cmd->add_option("--out", args->out, "also write each garment's OBJ, body OBJ, previews and seam lengths into this folder");
  cmd->add_option("--data", args->data,
                  "reference data folder: also bench its GarmentCode references (e.g. ../shared/data)");
  cmd->callback([args, solver] {
    args->solver_auto = solver->count() == 0;
    run_bench_garment(*args);
  });
}

}  // namespace tp::host::cli
