// host/bench/rip_bench.h: `printctl bench rip`: RIP throughput, memory against roll length, and the
// comparison with Ghostscript's tiffsep1 on the same image.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "host/bench/child_process.h"
#include "rip/common/error.h"

namespace tp::rip {

struct RipBenchOptions {
  double width_m = 1.6;
  double length_m = 1.0;                   ///< roll length of the throughput runs
  /// "garment": the sample skirt's projected design through the design renderer, nested;
  /// "panels": planar projections on sewn flat panels covering the roll, through the same renderer;
  /// "textured": the stand-in renderer over full-coverage textured rectangles.
  std::string renderer = "panels";
  int passes = 1;
  int threads = 0;                         ///< 0: all cores
  bool vs_ghostscript = false;
  std::vector<double> rss_lengths_m{1, 20};  ///< peak memory probes (each its own child process)
  double ghostscript_area_m2 = 0.1;        ///< square image for the Ghostscript comparison
  std::filesystem::path work_dir;          ///< scratch files; empty: a fresh temp folder, removed after
};

/// Runs the benchmark at 600 x 600 dpi, 4 inks, 2-bit drops (the default printer model), printing
/// key=value figures through `emit` as they come:
///  - renderer: which job (see RipBenchOptions::renderer), coverage (inked share of the roll);
///  - (a) the whole RIP with rendering on that marker: m2_per_hour (wall),
///    cpu_m2_per_hour (as if the threads had their cores alone: area over CPU time per thread),
///    render_m2_per_hour (rendering alone on the same threads), per-stage ns_per_px (CPU),
///    compression_ratio, peak_rss_mb;
///  - (b) the pipeline after rendering (rows replayed from memory): after_render_m2_per_hour;
///  - peak_rss_mb_<L>m for each probe length and rss_growth_pct (longest vs shortest);
///  - with vs_ghostscript: ghostscript_m2_per_hour, rip_1bit_m2_per_hour and ratio_vs_ghostscript,
///    both making 1-bit CMYK separation TIFFs of the same JPEG-in-PDF at 600 dpi.
/// Every measurement runs in its own child process. Must be called while the process has one thread.
/// Fails with the first measurement's error.
[[nodiscard]] Status run_rip_bench(const RipBenchOptions& options, const FigureSink& emit);

}  // namespace tp::rip
