// host/app/printctl/cmd_colour.cpp: colour commands: `printctl calibrate` makes a calibration
// set; `printctl proof-check <out>` compares a job's design (marker.png) with its printed
// fabric's colour (fabric-lab.tif).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "host/app/printctl/commands.h"
#include "host/calibration/calibrate.h"
#include "rip/colour/lab_image.h"
#include "rip/colour/proof_check.h"
#include "rip/colour/soft_proof.h"
#include "rip/image/image_io.h"

namespace tp::host::cli {

namespace {

struct ProofCheckArgs {
  std::string out;
  std::string design = "marker.png";
  std::string fabric = "fabric-lab.tif";
  double cell_mm = 0;  ///< 0: the job's descreening aperture (descreen_cell_mm)
  std::string profile;
};

/// Without a scan's own choice, the job's fabric is descreened as its printed seams are: the
/// aperture report.json records beside them (12 drop pitches, at least 1 mm: 2.03 mm at 150 dpi,
/// 1.02 mm at 300 dpi). A 1 mm cell at 150 dpi holds 6 x 6 drop pitches and measures the screen's
/// grain with the colour (docs/colour.md). 1 mm when the folder has no such report (a scan).
double descreen_cell_mm(const std::filesystem::path& out) {
  std::ifstream in(out / "report.json");
  const nlohmann::json r = nlohmann::json::parse(in, nullptr, false);
  if (!r.is_discarded())
    for (const char* key : {"seams_printed", "allowance_printed"})
      if (r.contains(key) && r[key].is_object() && r[key].contains("aperture_mm") && r[key]["aperture_mm"].is_number())
        return r[key]["aperture_mm"].get<double>();
  return 1.0;
}

}  // namespace

void register_colour_commands(CLI::App& app) {
  auto c = std::make_shared<CalibrateOptions>();
  auto printer = std::make_shared<std::string>(), measurements = std::make_shared<std::string>();
  auto precondition = std::make_shared<std::string>();
  CLI::App* cal = app.add_subcommand("calibrate", "Print and measure a profiling chart, build the ICC profile (ArgyllCMS)");
  cal->add_option("--printer", *printer, "Printer model file (.tpm); the built-in model otherwise");
  cal->add_option("--fabric", c->fabric, "Fabric preset loaded in the printer")
      ->check(CLI::IsMember({"cotton", "polyester-satin", "silk"}))
      ->capture_default_str();
  cal->add_option("--out", c->out, "Calibration set folder to write")->required();
  cal->add_option("--measurements", *measurements, "A real instrument's .ti3 of the chart: build from it, print nothing");
  cal->add_option("--patches", c->patches, "Profiling chart patches (targen -f)")->check(CLI::Range(800, 5000))->capture_default_str();
  cal->add_option("--dpi", c->dpi, "Chart print resolution")->check(CLI::Range(50, 1200))->capture_default_str();
  cal->add_option("--aperture-mm", c->aperture_mm, "Simulated instrument aperture")->capture_default_str();
  cal->add_option("--noise", c->noise_de, "Simulated instrument noise per L*, a*, b*")->capture_default_str();
  cal->add_option("--quality", c->quality, "colprof quality: l, m, h")->check(CLI::IsMember({"l", "m", "h"}))->capture_default_str();
  cal->add_option("--passes", c->passes, "Charts printed; each after the first spread by the profile so far")
      ->check(CLI::Range(1, 3))
      ->capture_default_str();
  cal->add_option("--precondition", *precondition,
                  "A first profile of this printer and fabric: spread the patches evenly in colour (targen -c)");
  cal->add_option("--drop-limit-de00", c->drop_limit_de00,
                  "Drop limit: the amount at which an ink comes within this of its heaviest patch")
      ->check(CLI::Range(0.1, 10.0))
      ->capture_default_str();
  auto no_ink_charts = std::make_shared<bool>(false);
  cal->add_flag("--no-ink-charts", *no_ink_charts,
                "Skip the drop-limit, linearisation and ink-limit charts (the profile alone)");
  auto no_light_chart = std::make_shared<bool>(false);
  cal->add_flag("--no-light-chart", *no_light_chart,
                "Skip the light-colour chart (343 patches in the light corner of device RGB)");
  cal->callback([c, printer, measurements, precondition, no_ink_charts, no_light_chart] {
    c->ink_charts = !*no_ink_charts;
    c->light_chart = !*no_light_chart;
    if (!printer->empty()) c->printer_model = *printer;
    if (!precondition->empty()) c->precondition = *precondition;
    if (!measurements->empty()) c->measurements = *measurements;
    auto r = calibrate(*c);
    if (!r) {
      std::fprintf(stderr, "printctl calibrate: %s\n", r.error().what().c_str());
      throw CLI::RuntimeError(1);
    }
    std::printf(
        "patches=%d\nchart_area_m2=%.4f\nseconds=%.1f\nfit_de00_mean=%.3f\nfit_de00_max=%.3f\nprofile=%s\n"
        "ink_charts=%d\nink_limit_percent=%.0f\n",
        r->patches, r->chart_area_m2, r->seconds, r->fit_mean_de00, r->fit_max_de00, r->profile.c_str(), r->ink_charts,
        r->ink_limit_percent);
  });

  auto sp = std::make_shared<ProofCheckArgs>();
  CLI::App* soft = app.add_subcommand(
      "soft-proof", "Render a job's marker.png as the calibrated printer reproduces it (marker-proof.png, -gamut.png)");
  soft->add_option("out", sp->out, "A job's output folder")->required();
  soft->add_option("--design", sp->design, "Design image inside it")->capture_default_str();
  soft->add_option("--profile", sp->profile, "Printer profile (a calibration set's profile.icc)")->required();
  soft->callback([sp] {
    const std::filesystem::path dir(sp->out);
    auto fail_with = [](const std::string& m) {
      std::fprintf(stderr, "printctl soft-proof: %s\n", m.c_str());
      throw CLI::RuntimeError(1);
    };
    auto design = rip::read_image(dir / sp->design);
    if (!design) fail_with(design.error().what());
    geometry::ImageRgba8 proof, overlay;
    auto s = rip::soft_proof(*design, sp->profile, proof, &overlay);
    if (!s) fail_with(s.error().what());
    const std::string stem = std::filesystem::path(sp->design).stem().string();
    // The design's own resolution carries over (marker.png has pHYs).
    double dpi = 0;
    if (auto r = rip::read_image3f(dir / sp->design)) dpi = r->px_per_mm * 25.4;
    for (const auto& [img, name] : {std::pair{&proof, stem + "-proof.png"}, std::pair{&overlay, stem + "-gamut.png"}})
      if (auto w = rip::write_png(dir / name, *img, rip::PngChannels::kRgba, dpi); !w) fail_with(w.error().what());
    std::printf("printed_pixels=%zu\nout_of_gamut_share=%.4f\nworst_de00=%.2f\nproof=%s\n", s->printed_pixels,
                s->out_of_gamut_share, s->worst_de00, (dir / (stem + "-proof.png")).c_str());
  });

  auto a = std::make_shared<ProofCheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "proof-check", "CIEDE2000 between a job's design and its printed fabric over the printed area (key=value)");
  cmd->add_option("out", a->out, "A job's output folder (printctl run --out)")->required();
  cmd->add_option("--design", a->design, "Design image inside it (sRGB, white = unprinted)")->capture_default_str();
  cmd->add_option("--fabric", a->fabric, "Printed fabric colour inside it (CIELAB TIFF)")->capture_default_str();
  cmd->add_option("--cell-mm", a->cell_mm,
                  "Descreening cell size (default: the job's printed-seam aperture in report.json, else 1 mm)")
      ->check(CLI::Range(0.1, 50.0));
  cmd->add_option("--profile", a->profile, "Printer profile (a calibration set's): leave out-of-gamut colours out, count them");
  cmd->callback([a] {
    const std::filesystem::path dir(a->out);
    const double cell_mm = a->cell_mm > 0 ? a->cell_mm : descreen_cell_mm(dir);
    auto r = rip::check_proof(dir / a->design, dir / a->fabric, cell_mm, a->profile);
    if (!r) {
      std::fprintf(stderr, "printctl proof-check: %s\n", r.error().what().c_str());
      throw CLI::RuntimeError(1);
    }
    std::printf(
        "cells=%zu\ncell_mm=%.2f\nblank_cells=%zu\nedge_cells=%zu\nde00_mean=%.3f\nde00_p95=%.3f\nde00_max=%.3f\n"
        "fabric_white_lab=%.2f,%.2f,%.2f\nout_of_gamut_share=%.4f\nout_of_gamut_worst_de00=%.2f\nbias_lab=%.2f,%.2f,%."
        "2f\n",
        r->cells, r->cell_mm, r->blank_cells, r->edge_cells, r->mean_de00, r->p95_de00, r->max_de00, r->fabric_white.l,
        r->fabric_white.a, r->fabric_white.b, r->out_of_gamut_share, r->out_of_gamut_worst_de00, r->bias.l, r->bias.a,
        r->bias.b);
  });
}

}  // namespace tp::host::cli
