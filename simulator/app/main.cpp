// simulator/app/main.cpp: the printsim command line: `printsim run [options] -- <command> [args]`
// runs a command against the simulated printer and cutting table; `printsim model` prints the
// built-in printer model file.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <iostream>

#include "device/model/printer_model_file.h"
#include "simulator/fabric/spectro_measure.h"
#include "simulator/internal/sim_log.h"
#include "simulator/printsim/printer_sim.h"

int main(int argc, char** argv) {
  CLI::App app{"printsim: the virtual textile printer and cutting table behind umockdev"};
  app.require_subcommand(1);

  tp::sim::SimOptions opt;
  std::string scenario, model;
  bool verbose = false;
  CLI::App* run = app.add_subcommand("run", "Run a command against the emulated USB printer and GPIO chip");
  run->add_option("--out", opt.out_dir, "Folder for fabric.tif, fabric.png and printer.json")->capture_default_str();
  run->add_flag("--job-dirs", opt.job_dirs, "Write each job into <out>/<job name>/");
  run->add_option("--scenario", scenario, "Fault-injection scenario (JSON, docs/simulator.md)");
  run->add_option("--printer", model, "Printer model file (.tpm); the built-in tp-sim-1600 otherwise");
  run->add_option("--speed", opt.speed, "Modelled seconds per wall second (0: as fast as data arrives)")
      ->check(CLI::Range(0.0, 1000.0));
  run->add_flag("--no-fabric", [&](std::int64_t) { opt.fabric = false; }, "Do not lay drops or write images");
  run->add_option("--reap-hold-ms", opt.reap_hold_ms, "Hold empty URB reaps this long (0: answer at once)")
      ->check(CLI::Range(0u, 100u));
  std::string state;
  run->add_option("--state", state,
                  "The printer's non-volatile memory file: kept across runs, so a printsim killed mid-job "
                  "comes back as a printer that lost power");
  run->add_flag("-v,--verbose", verbose, "Log devices, jobs and faults to stderr");
  run->add_option("command", opt.command, "Command and arguments (after --)")->required();

  CLI::App* show = app.add_subcommand("model", "Print the built-in printer model file");

  tp::sim::MeasureOptions mo;
  CLI::App* measure = app.add_subcommand("measure", "Read a chart's patches off a printed fabric (simulated spectrophotometer)");
  measure->add_option("--chart", mo.chart, "Chart layout (CGATS with SAMPLE_ID, TP_X_MM, TP_Y_MM, device values)")->required();
  measure->add_option("--fabric", mo.fabric_lab, "The printed fabric's fabric-lab.tif")->required();
  measure->add_option("--out", mo.out_ti3, "Measurements (.ti3) to write")->required();
  measure->add_option("--aperture-mm", mo.aperture_mm, "Measured spot diameter")->capture_default_str();
  measure->add_option("--noise", mo.noise_de, "Standard deviation of noise per L*, a*, b* (0: none)")
      ->check(CLI::Range(0.0, 10.0))->capture_default_str();
  measure->add_option("--seed", mo.seed, "Noise seed")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (show->parsed()) {
    std::cout << tp::device::format_printer_model(tp::device::PrinterModel{});
    return 0;
  }
  if (measure->parsed()) {
    auto m = tp::sim::measure_chart(mo);
    if (!m) {
      std::fprintf(stderr, "printsim measure: %s\n", m.error().what().c_str());
      return 1;
    }
    std::printf("patches=%zu min_samples=%.0f out=%s\n", m->patches, m->min_samples, mo.out_ti3.c_str());
    return 0;
  }
  if (verbose) tp::sim::sim_log()->set_level(spdlog::level::info);
  if (!scenario.empty()) opt.scenario = scenario;
  if (!model.empty()) opt.printer_model = model;
  if (!state.empty()) opt.state_file = state;
  auto r = tp::sim::run_printsim(opt);
  if (!r) {
    std::fprintf(stderr, "printsim: %s\n", r.error().what().c_str());
    return 125;
  }
  return *r;
}
