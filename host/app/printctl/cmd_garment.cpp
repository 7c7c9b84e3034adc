// host/app/printctl/cmd_garment.cpp: `printctl garment`: writes a sample garment's pattern, 3D garment,
// dress form and previews.
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/garment/distortion.h"
#include "geometry/pattern/pattern_json.h"
#include "geometry/samples/garments.h"
#include "host/app/printctl/commands.h"
#include "host/pipeline/garment_files.h"

namespace tp::host::cli {
namespace {

struct GarmentArgs {
  std::string name;
  std::string size = "M";
  std::string out;
  double edge_mm = 20;
  int threads = 2;
};

[[noreturn]] void die(const std::string& msg, int code) {
  std::fprintf(stderr, "printctl garment: %s\n", msg.c_str());
  throw CLI::RuntimeError(code);
}


nlohmann::json report_json(const geometry::DistortionReport& r, const geometry::SewStats& st) {
  nlohmann::json seams = nlohmann::json::array();
  for (const auto& s : r.seams)
    seams.push_back({{"stitch", s.stitch}, {"a_mm", s.a_mm}, {"b_mm", s.b_mm}, {"sewn_mm", s.sewn_mm}, {"diff", s.diff}});
  return {{"vertices", r.vertices}, {"triangles", r.triangles}, {"strain_mean", r.strain_mean},
          {"strain_p95", r.strain_p95}, {"strain_max", r.strain_max}, {"area_change", r.area_change},
          {"seam_len_diff_max", r.seam_len_diff_max}, {"inside_body", r.inside_body},
          {"min_clearance_mm", r.min_clearance_mm}, {"seconds", st.seconds}, {"seams", seams}};
}

void run_garment(const GarmentArgs& a) {
  geometry::SewOptions o;
  o.target_edge_mm = a.edge_mm;
  o.threads = a.threads;
  auto g = geometry::samples::make_garment(a.name, a.size, o);
  if (!g) die(g.error().what(), 2);
  std::filesystem::path dir(a.out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) die(a.out + ": " + ec.message(), 1);

  if (auto s = geometry::save_pattern_json(g->pattern, dir / (a.name + ".pattern.json")); !s) die(s.error().what(), 1);
  if (auto st = write_garment_files(dir, a.name, g->pattern, g->garment, g->body->mesh(), "dress_form"); !st)
    die(st.error().what(), 1);
  geometry::DistortionReport r = geometry::measure_distortion(g->pattern, g->garment, g->body.get());
  nlohmann::json j{{"garment", a.name}, {"size", a.size}, {"pieces", g->pattern.pieces.size()},
                   {"stitches", g->pattern.stitches.size()}, {"distortion", report_json(r, g->stats)}};
  if (auto st = write_text_file(dir / "report.json", j.dump(2) + "\n"); !st) die(st.error().what(), 1);
  std::printf("garment=%s size=%s pieces=%zu vertices=%d strain_mean=%.4f strain_p95=%.4f seam_len_diff_max=%.4f "
              "inside_body=%d seconds=%.2f out=%s\n",
              a.name.c_str(), a.size.c_str(), g->pattern.pieces.size(), r.vertices, r.strain_mean, r.strain_p95,
              r.seam_len_diff_max, r.inside_body, g->stats.seconds, a.out.c_str());
}

}  // namespace

void register_garment_commands(CLI::App& app) {
  auto args = std::make_shared<GarmentArgs>();
  CLI::App* cmd = app.add_subcommand("garment", "Draft a sample garment, sew it on its dress form, write pattern, OBJ and previews");
  cmd->add_option("name", args->name, "simple_top, blouse, dress or skirt8")->required();
  cmd->add_option("--size", args->size, "S, M, L, measurements (bust=940,waist=760) or both (L:hips=1120)");
  cmd->add_option("--out", args->out, "output folder")->required();
  cmd->add_option("--edge-mm", args->edge_mm, "target triangle edge length, mm")->check(CLI::Range(3.0, 200.0));
  cmd->add_option("--threads", args->threads, "threads for sewing")->check(CLI::Range(1, 8));
  cmd->callback([args] { run_garment(*args); });
}

}  // namespace tp::host::cli
