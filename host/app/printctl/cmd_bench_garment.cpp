// host/app/printctl/cmd_bench_garment.cpp: `printctl bench garment`: builds garments at a given vertex
// count and prints their distortion figures and build time (issue 4's figures).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/body/load_body_obj.h"
#include "geometry/garment/distortion.h"
#include "geometry/garment/sew_garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/garmentcode.h"
#include "geometry/pattern/pattern_json.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "host/app/printctl/commands.h"
#include "host/pipeline/garment_files.h"

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
  geometry::SewOptions sew;  ///< solver settings other than mesh size and threads
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
    char nums[160];
    std::snprintf(nums, sizeof nums, " a_mm=%.2f b_mm=%.2f sewn_mm=%.2f diff=%.4f\n", sl.a_mm, sl.b_mm, sl.sewn_mm, sl.diff);
    out += std::to_string(sl.stitch) + " " + side(st.a) + " " + side(st.b) + nums;
  }
  return out;
}

// Meshes `pattern` for about `vertices` vertices, sews it on `body` and prints one line.
void bench_one(const std::string& name, const geometry::Pattern& pattern, const geometry::BodySdf& body,
               const BenchGarmentArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  geometry::SewOptions o = a.sew;
  o.target_edge_mm = geometry::target_edge_for_vertex_count(pattern, a.vertices);
  o.threads = a.threads;
  auto g = geometry::sew_garment(pattern, body, o);
  if (!g) die(name + ": " + g.error().what(), 1);
  const double seconds = since(t0);
  geometry::DistortionReport r = geometry::measure_distortion(pattern, *g, &body);
  if (!a.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (ec) die(a.out + ": " + ec.message(), 1);
    if (auto st = write_garment_files(a.out, name, pattern, *g, body.mesh(), name + "_body"); !st) die(st.error().what(), 1);
    if (auto st = write_text_file(std::filesystem::path(a.out) / (name + "_seams.txt"), seam_lines(pattern, r)); !st)
      die(st.error().what(), 1);
  }
  std::printf("garment=%s vertices=%d strain_mean=%.4f strain_p95=%.4f seam_len_diff_max=%.4f inside_body=%d seconds=%.2f\n",
              name.c_str(), r.vertices, r.strain_mean, r.strain_p95, r.seam_len_diff_max, r.inside_body, seconds);
  std::fflush(stdout);
}

geometry::Pattern load_pattern(const std::string& path) {
  // GarmentCode specifications hold a "panels" object; anything else is the native format.
  auto gc = geometry::load_garmentcode(path);
  if (gc) return std::move(*gc);
  auto native = geometry::load_pattern_json(path);
  if (!native) die(native.error().what(), 2);
  return std::move(*native);
}

std::shared_ptr<const geometry::BodySdf> load_body(const std::string& path, double mm_per_unit) {
  auto mesh = geometry::load_body_obj(path, mm_per_unit);
  if (!mesh) die(mesh.error().what(), 2);
  auto sdf = geometry::BodySdf::build(std::move(*mesh));
  if (!sdf) die(sdf.error().what(), 2);
  return std::make_shared<const geometry::BodySdf>(std::move(*sdf));
}

void run_bench_garment(const BenchGarmentArgs& a) {
  if (!a.pattern.empty()) {
    if (a.body.empty()) die("--pattern needs --body", 2);
    auto body = load_body(a.body, a.body_mm_per_unit);
    geometry::Pattern p = load_pattern(a.pattern);
    bench_one(std::filesystem::path(a.pattern).stem().string(), p, *body, a);
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
    bench_one(name, *p, **body, a);
  }
  if (!a.garment.empty()) return;
  // The GarmentCode references on their average female body.
  std::filesystem::path data = a.data;
  auto mean_female = load_body((data / "garmentcode/bodies/mean_female.obj").string(), 1000);
  for (const char* spec : {"dress_pencil", "shirt_mean"}) {
    auto path = data / "garmentcode/patterns" / (std::string(spec) + "_specification.json");
    auto p = geometry::load_garmentcode(path);
    if (!p) die(p.error().what(), 2);
    bench_one(spec, *p, *mean_female, a);
  }
}

}  // namespace

void register_bench_garment(CLI::App& bench) {
  auto args = std::make_shared<BenchGarmentArgs>();
  const char* env = std::getenv("TP_SHARED_DATA");
  args->data = env ? env : "../shared/data";
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
  cmd->add_option("--clearance-mm", args->sew.clearance_mm, "distance the garment keeps from the body")
      ->check(CLI::Range(0.0, 50.0));
  cmd->add_option("--seam-edge-weight", args->sew.seam_edge_weight, "stiffness of sewn seams against their pattern length")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--gravity", args->sew.gravity_per_mm, "weight per area relative to membrane stiffness")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--out", args->out, "also write each garment's OBJ, body OBJ, previews and seam lengths into this folder");
  cmd->add_option("--data", args->data, "shared reference data folder (default $TP_SHARED_DATA or ../shared/data)");
  cmd->callback([args] { run_bench_garment(*args); });
}

}  // namespace tp::host::cli
