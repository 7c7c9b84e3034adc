// host/app/printctl/cmd_bench_design.cpp: `printctl bench design`: samples the paper's designs
// onto the sample garments' pieces and prints seam and allowance continuity (CIEDE2000) and the
// time taken; `--throughput` measures the renderer alone at 600 dpi in RIP-sized bands.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/common/thread_pool.h"
#include "geometry/continuity/continuity.h"
#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/render_piece_image.h"
#include "geometry/design/sample_designs.h"
#include "geometry/samples/garments.h"
#include "host/app/printctl/commands.h"
#include "rip/image/image_io.h"

namespace tp::host::cli {
namespace {

struct BenchDesignArgs {
  std::vector<std::string> garments;
  double dpi = 300;
  std::string size = "M";
  int threads = 2;
  bool throughput = false;
  bool detail = false;
  std::string out;
};

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

[[noreturn]] void die(const std::string& what, int code) {
  std::fprintf(stderr, "printctl bench design: %s\n", what.c_str());
  throw CLI::RuntimeError(code);
}

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Renders every piece's bounding box at `dpi` in 64-row bands on `threads` threads of the pool,
// into one reused band buffer per worker as the RIP does (or whole images when `keep` asks for
// them); returns the pixels rendered.
std::size_t render_all(const geometry::PieceRenderer& r, double dpi, int threads, std::vector<geometry::PieceImage>* keep) {
  constexpr int kBand = 64;
  const int n = r.piece_count();
  std::vector<geometry::PieceImage> images(keep ? static_cast<size_t>(n) : 0);
  std::vector<std::size_t> pixels(static_cast<size_t>(n), 0);
  ThreadPool pool(std::max(1, threads));
  std::vector<std::vector<geometry::Rgba8>> bands(static_cast<size_t>(pool.size()));
  pool.parallel_for(n, [&](int p, int worker) {
    if (keep) {
      images[static_cast<size_t>(p)] = geometry::render_piece_image(r, p, dpi, 2, kBand);
      pixels[static_cast<size_t>(p)] = images[static_cast<size_t>(p)].image.pixels.size();
      return;
    }
    std::vector<geometry::Rgba8>& band = bands[static_cast<size_t>(worker)];
    const auto box = geometry::bounds(r.cut_outline_mm(p));
    const double mm = 25.4 / dpi;
    const int w = static_cast<int>(std::ceil(box.width() / mm)) + 1,
              h = static_cast<int>(std::ceil(box.height() / mm)) + 1;
    band.resize(static_cast<size_t>(w) * kBand);
    for (int y0 = 0; y0 < h; y0 += kBand) {
      std::fill(band.begin(), band.end(), geometry::Rgba8{});
      r.render(p, geometry::Affine2{mm, 0, box.min.x, 0, -mm, box.max.y - y0 * mm}, w, std::min(kBand, h - y0),
               band.data(), w);
    }
    pixels[static_cast<size_t>(p)] = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  });
  if (keep) *keep = std::move(images);
  std::size_t total = 0;
  for (std::size_t px : pixels) total += px;
  return total;
}

void bench_garment(const std::string& name, const BenchDesignArgs& a) {
  auto sample = geometry::samples::make_garment(name, a.size);
  if (!sample) die("garment '" + name + "': " + sample.error().what(), 2);
  const geometry::Design design = geometry::sample_design(name, sample->garment);
  geometry::Finishing finishing;
  finishing.job_name = "BENCH";
  geometry::RenderOptions options;
  options.build_threads = a.threads;

  const double t0 = now_s(), c0 = process_cpu_s();
  auto renderer = geometry::make_piece_renderer(sample->pattern, sample->garment, design, finishing, options);
  if (!renderer) die("garment '" + name + "': " + renderer.error().what(), 1);
  const double t1 = now_s();
  std::vector<geometry::PieceImage> images;
  const std::size_t px = render_all(**renderer, a.dpi, a.threads, a.out.empty() ? nullptr : &images);
  const double t2 = now_s(), c2 = process_cpu_s();
  geometry::ContinuityOptions measure;
  measure.threads = a.threads;
  auto rep = geometry::measure_continuity(sample->pattern, sample->garment, finishing, **renderer, a.dpi, measure);
  if (!rep) die("garment '" + name + "': " + rep.error().what(), 1);
  const double t3 = now_s();
  std::printf(
      "garment=%s dpi=%g seam_de00_mean=%.3f seam_de00_p95=%.3f seam_de00_max=%.3f allowance_de00_p95=%.3f "
      "seconds=%.2f build_seconds=%.2f render_seconds=%.2f cpu_seconds=%.2f mpx=%.1f seam_samples=%zu "
      "allowance_samples=%zu allowance_de00_mean=%.3f layers=%zu continuity_seconds=%.2f threads=%d\n",
      name.c_str(), a.dpi, rep->seams.mean, rep->seams.p95, rep->seams.max, rep->allowance.p95, t2 - t0, t1 - t0,
      t2 - t1, c2 - c0, static_cast<double>(px) / 1e6, rep->seams.samples, rep->allowance.samples, rep->allowance.mean,
      design.layers.size(), t3 - t2, measure.threads);
  if (a.detail) {
    for (const auto& sc : rep->seam_list)
      std::printf("  seam %s.%s ~ %s.%s samples=%zu de00_mean=%.3f de00_p95=%.3f de00_max=%.3f\n", sc.piece_a.c_str(),
                  sc.edge_a.c_str(), sc.piece_b.c_str(), sc.edge_b.c_str(), sc.de00.samples, sc.de00.mean, sc.de00.p95,
                  sc.de00.max);
    for (const auto& al : rep->allowance_list)
      std::printf("  allowance %s.%s from %s (category %d) samples=%zu de00_mean=%.3f de00_p95=%.3f de00_max=%.3f\n",
                  al.piece.c_str(), al.edge.c_str(), al.source_piece.c_str(), al.category, al.de00.samples, al.de00.mean,
                  al.de00.p95, al.de00.max);
    for (const auto* list : {&rep->worst_seam_samples, &rep->worst_allowance_samples})
      for (const auto& w : *list)
        std::printf("  worst %s de00=%.2f %s(%.2f,%.2f)=#%02x%02x%02x%02x %s(%.2f,%.2f)=#%02x%02x%02x%02x\n",
                    list == &rep->worst_seam_samples ? "seam" : "allowance", w.de00, w.piece_a.c_str(), w.at_a_mm.x,
                    w.at_a_mm.y, w.colour_a.r, w.colour_a.g, w.colour_a.b, w.colour_a.a, w.piece_b.c_str(), w.at_b_mm.x,
                    w.at_b_mm.y, w.colour_b.r, w.colour_b.g, w.colour_b.b, w.colour_b.a);
  }
  std::fflush(stdout);
  if (a.out.empty()) return;
  std::filesystem::create_directories(a.out);
  for (size_t p = 0; p < images.size(); ++p) {
    const auto path = std::filesystem::path(a.out) / (name + "_" + sample->pattern.pieces[p].name + ".png");
    if (auto st = rip::write_png(path, images[p].image); !st) die(st.error().what(), 1);
  }
}

// Renderer throughput: the skirt's marbling (cylindrical) and motif (planar) at 600 dpi in 64-row
// bands across a piece's bounding box, as the RIP calls it; wall time and thread CPU time.
void bench_throughput(const BenchDesignArgs& a) {
  auto sample = geometry::samples::make_garment("skirt8", a.size);
  if (!sample) die("skirt8: " + sample.error().what(), 2);
  const geometry::Design marbling = geometry::sample_design("skirt8", sample->garment);
  geometry::Design motif = geometry::sample_design("dress", sample->garment);
  motif.layers.erase(motif.layers.begin());
  std::get<geometry::PlanarProjection>(motif.layers[0].content).repeat = true;
  for (const auto& [label, design] : {std::pair{"cylindrical", marbling}, std::pair{"planar", motif}}) {
    geometry::Finishing finishing;
    finishing.marks = geometry::MarkMode::kNone;
    auto r = geometry::make_piece_renderer(sample->pattern, sample->garment, design, finishing);
    if (!r) die(r.error().what(), 1);
    // The largest piece, its bounding box cut into RIP bands.
    int piece = 0;
    double area = 0;
    for (int p = 0; p < (*r)->piece_count(); ++p) {
      const auto b = geometry::bounds((*r)->cut_outline_mm(p));
      if (b.width() * b.height() > area) area = b.width() * b.height(), piece = p;
    }
    const auto box = geometry::bounds((*r)->cut_outline_mm(piece));
    const double mm = 25.4 / 600;
    const int w = static_cast<int>(std::ceil(box.width() / mm)), h = static_cast<int>(std::ceil(box.height() / mm));
    constexpr int kBand = 64;
    const int bands = (h + kBand - 1) / kBand;
    for (int threads : {1, a.threads}) {
      ThreadPool pool(threads);
      std::vector<std::vector<geometry::Rgba8>> bufs(static_cast<size_t>(pool.size()),
                                                     std::vector<geometry::Rgba8>(static_cast<size_t>(w) * kBand));
      std::vector<std::size_t> covered(static_cast<size_t>(bands), 0);
      std::vector<double> cpu(static_cast<size_t>(pool.size()), 0.0);
      const double t0 = now_s();
      pool.parallel_for(bands, [&](int b, int worker) {
        const double c0 = thread_cpu_s();
        std::vector<geometry::Rgba8>& buf = bufs[static_cast<size_t>(worker)];
        std::fill(buf.begin(), buf.end(), geometry::Rgba8{});
        const geometry::Affine2 m{mm, 0, box.min.x, 0, -mm, box.max.y - b * kBand * mm};
        (*r)->render(piece, m, w, kBand, buf.data(), w);
        std::size_t mine = 0;
        for (const auto& p : buf) mine += p.a > 0;
        covered[static_cast<size_t>(b)] = mine;
        cpu[static_cast<size_t>(worker)] += thread_cpu_s() - c0;
      });
      const double wall = now_s() - t0;
      double cpu_total = 0;
      for (double c : cpu) cpu_total += c;
      std::size_t covered_px = 0;
      for (std::size_t c : covered) covered_px += c;
      const double window_px = static_cast<double>(w) * kBand * bands;
      std::printf(
          "render=%s dpi=600 threads=%d window_mpx=%.1f covered_mpx=%.1f wall_mpx_per_s=%.1f "
          "covered_mpx_per_s=%.1f cpu_mpx_per_cpu_s=%.1f\n",
          label, threads, window_px / 1e6, static_cast<double>(covered_px) / 1e6, window_px / wall / 1e6,
          static_cast<double>(covered_px) / wall / 1e6, window_px / cpu_total / 1e6);
      std::fflush(stdout);
    }
  }
}

void run(const BenchDesignArgs& a) {
  if (a.throughput) {
    bench_throughput(a);
    return;
  }
  std::vector<std::string> names = a.garments;
  if (names.empty()) names = geometry::samples::garment_names();
  for (const std::string& n : names) bench_garment(n, a);
}

}  // namespace

void register_bench_design(CLI::App& bench) {
  auto args = std::make_shared<BenchDesignArgs>();
  CLI::App* cmd = bench.add_subcommand(
      "design", "Sample the paper's designs onto the sample garments; print seam/allowance dE00 and time");
  cmd->add_option("--garment", args->garments, "sample garment (repeatable; default: all four)");
  cmd->add_option("--dpi", args->dpi, "sampling resolution")->check(CLI::PositiveNumber);
  cmd->add_option("--size", args->size, "garment size (see printctl garment)");
  cmd->add_option("--threads", args->threads, "threads for building, rendering and measuring")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--throughput", args->throughput, "measure render throughput at 600 dpi instead");
  cmd->add_option("--out", args->out, "write each rendered piece as a PNG here");
  cmd->add_flag("--detail", args->detail, "also print every seam's and every allowance's figures");
  cmd->callback([args] { run(*args); });
}

}  // namespace tp::host::cli
