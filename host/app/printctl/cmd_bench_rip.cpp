// host/app/printctl/cmd_bench_rip.cpp: `printctl bench rip`: RIP throughput, peak memory against roll
// length and the Ghostscript comparison, as key=value lines (see host/bench/rip_bench.h).
#include <cstdio>
#include <sstream>
#include <string>

#include "host/app/printctl/commands.h"
#include "host/bench/rip_bench.h"

namespace tp::host::cli {

namespace {

/// "1,20" -> {1, 20}; throws CLI::ValidationError on junk.
std::vector<double> parse_lengths(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      const double v = std::stod(item, &used);
      if (used != item.size() || !(v > 0)) throw std::invalid_argument(item);
      out.push_back(v);
    } catch (const std::exception&) {
      throw CLI::ValidationError("--rss-lengths", "'" + item + "' is not a positive length in metres");
    }
  }
  return out;
}

}  // namespace

void register_bench_rip(CLI::App& bench) {
  auto opts = std::make_shared<rip::RipBenchOptions>();
  auto rss = std::make_shared<std::string>("1,20");
  CLI::App* cmd = bench.add_subcommand(
      "rip", "RIP throughput (m2/h at 600 dpi, 4 inks, 2-bit, full-coverage marker), peak memory, vs Ghostscript");
  cmd->add_option("--length-m", opts->length_m, "Roll length of the throughput runs, metres")->capture_default_str();
  cmd->add_option("--width-m", opts->width_m, "Fabric width, metres")->capture_default_str();
  cmd->add_option("--passes", opts->passes, "Print passes (1, 2, 4, 8)")->capture_default_str();
  cmd->add_option("--renderer", opts->renderer,
                  "garment: the sample skirt's projected design, nested; panels: projected design on panels "
                  "covering the roll; textured: stand-in rectangles")
      ->check(CLI::IsMember({"garment", "panels", "textured"}))
      ->capture_default_str();
  cmd->add_option("--threads", opts->threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd->add_option("--rss-lengths", *rss, "Roll lengths (m) whose peak memory is measured, comma-separated")
      ->capture_default_str();
  cmd->add_flag("--vs-ghostscript", opts->vs_ghostscript,
                "Also time gs -sDEVICE=tiffsep1 -r600 against this RIP on the same 0.1 m2 JPEG-in-PDF");
  cmd->add_option("--work-dir", opts->work_dir, "Keep the Ghostscript comparison files here");
  cmd->callback([opts, rss] {
    opts->rss_lengths_m = parse_lengths(*rss);
    auto status = rip::run_rip_bench(*opts, [](std::string_view k, std::string_view v) {
      std::printf("%.*s=%.*s\n", static_cast<int>(k.size()), k.data(), static_cast<int>(v.size()), v.data());
      std::fflush(stdout);
    });
    if (!status) {
      std::fprintf(stderr, "bench rip: %s\n", status.error().what().c_str());
      throw CLI::RuntimeError(1);
    }
  });
}

}  // namespace tp::host::cli
