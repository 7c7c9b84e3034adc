// host/bench/rip_bench.cpp: the RIP benchmark's measurements, each in a child process.
#include "host/bench/rip_bench.h"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>

#include <spdlog/fmt/fmt.h>

#include "host/bench/bench_marker.h"
#include "host/bench/pdf_image.h"
#include "rip/image/image_io.h"
#include "rip/job/rip_job.h"
#include "rip/render/image_file_source.h"
#include "rip/render/marker_source.h"

extern char** environ;

namespace tp::rip {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kReplayTiles = 48;   ///< render tiles rendered once for the after-rendering run
constexpr double kSecondsPerHour = 3600;

std::string num(double v, int decimals = 1) { return fmt::format("{:.{}f}", v, decimals); }

Status discard(device::Swath&&) { return {}; }

RipSettings bench_settings(const RipBenchOptions& o) {
  RipSettings s;
  s.passes = o.passes;
  s.threads = o.threads;
  return s;
}

/// (a): the whole RIP on the job's marker.
Status measure_whole(const RipBenchOptions& o, const BenchJob& job, const FigureSink& emit) {
  const geometry::Marker marker = repeat_block(job.block, o.length_m * 1000);
  const device::PrinterModel printer;
  const auto t0 = Clock::now();
  auto st = rip_marker(marker, *job.renderer, printer, bench_settings(o), discard);
  if (!st) return std::unexpected(st.error());
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double px = static_cast<double>(st->width_px) * st->height_px;
  const double stage_cpu = st->render_cpu_s + st->colour_cpu_s + st->screen_cpu_s + st->swath_cpu_s;
  emit("area_m2", num(st->area_m2, 3));
  emit("threads", std::to_string(st->threads));
  emit("m2_per_hour", num(st->area_m2 / wall * kSecondsPerHour));
  emit("render_m2_per_hour", num(st->area_m2 / (st->render_cpu_s / st->threads) * kSecondsPerHour));
  emit("stages_cpu_m2_per_hour", num(st->area_m2 / (stage_cpu / st->threads) * kSecondsPerHour));
  emit("render_ns_per_px", num(st->render_cpu_s / px * 1e9, 2));
  emit("colour_ns_per_px", num(st->colour_cpu_s / px * 1e9, 2));
  emit("screen_ns_per_px", num(st->screen_cpu_s / px * 1e9, 2));
  emit("swath_ns_per_px", num(st->swath_cpu_s / px * 1e9, 2));
  std::uint64_t inked = 0;
  for (const auto& d : st->drops) inked += d[1] + d[2] + d[3];
  emit("drops_per_px", num(static_cast<double>(inked) / px, 3));
  emit("swaths", std::to_string(st->swaths));
  emit("compression_ratio", num(st->compression_ratio, 3));
  emit("wall_s", num(wall, 2));
  return {};
}

/// (b): the pipeline after rendering, rows replayed from memory.
Status measure_after_render(const RipBenchOptions& o, const BenchJob& job, const FigureSink& emit) {
  const geometry::Marker marker = repeat_block(job.block, o.length_m * 1000);
  const device::PrinterModel printer;
  auto src = MarkerSource::create(marker, *job.renderer, printer.dpi_x, printer.dpi_y);
  if (!src) return std::unexpected(src.error());
  const auto block_rows = static_cast<std::int64_t>(job.block.length_mm * printer.dpi_y / 25.4);
  const ReplaySource replay(**src, kReplayTiles, block_rows, (*src)->height_px());
  const auto t0 = Clock::now();
  auto st = run_rip(replay, printer, bench_settings(o), discard);
  if (!st) return std::unexpected(st.error());
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  emit("after_render_m2_per_hour", num(st->area_m2 / wall * kSecondsPerHour));
  const double stage_cpu = st->render_cpu_s + st->colour_cpu_s + st->screen_cpu_s + st->swath_cpu_s;
  emit("after_render_cpu_m2_per_hour", num(st->area_m2 / (stage_cpu / st->threads) * kSecondsPerHour));
  return {};
}

std::string find_ghostscript() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t pos = 0;
  while (pos <= dirs.size()) {
    size_t colon = dirs.find(':', pos);
    if (colon == std::string::npos) colon = dirs.size();
    const std::filesystem::path p = std::filesystem::path(dirs.substr(pos, colon - pos)) / "gs";
    if (::access(p.c_str(), X_OK) == 0) return p.string();
    pos = colon + 1;
  }
  return {};
}

/// Runs Ghostscript's tiffsep1 on the PDF; returns wall seconds.
Result<double> run_ghostscript(const std::string& gs, const std::filesystem::path& dir) {
  const std::string out = "-sOutputFile=" + (dir / "gs_sep%d.tif").string();
  const std::string pdf = (dir / "image.pdf").string();
  std::vector<std::string> args{gs, "-q", "-dSAFER", "-dBATCH", "-dNOPAUSE", "-sDEVICE=tiffsep1", "-r600", out, pdf};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto t0 = Clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, gs.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    return fail(ErrorCode::kIo, "bench: cannot start " + gs);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return fail(ErrorCode::kIo, fmt::format("bench: ghostscript failed on {}", pdf));
  return wall;
}

/// The comparison image: the bench design rendered at 600 dpi, as JPEG and JPEG-in-PDF.
Status prepare_ghostscript_input(const RipBenchOptions& o, const std::filesystem::path& dir, const FigureSink& emit) {
  const double side_mm = std::sqrt(o.ghostscript_area_m2) * 1000;
  const BenchJob job = make_textured_bench_job(side_mm);
  const geometry::Marker marker = repeat_block(job.block, side_mm);
  auto src = MarkerSource::create(marker, *job.renderer, 600, 600);
  if (!src) return std::unexpected(src.error());
  geometry::ImageRgba8 img;
  img.width_px = (*src)->width_px();
  img.height_px = static_cast<int>((*src)->height_px());
  img.pixels.resize(static_cast<size_t>(img.width_px) * img.height_px);
  for (int y = 0; y < img.height_px; y += kRenderTileRows)
    (*src)->render_rows(y, std::min(kRenderTileRows, img.height_px - y), img.pixels.data() + static_cast<size_t>(y) * img.width_px,
                        img.width_px);
  if (auto s = write_jpeg(dir / "image.jpg", img, 90); !s) return s;
  std::ifstream f(dir / "image.jpg", std::ios::binary);
  std::vector<std::uint8_t> jpeg((std::istreambuf_iterator<char>(f)), {});
  emit("ghostscript_image_px", fmt::format("{}x{}", img.width_px, img.height_px));
  return write_jpeg_pdf(dir / "image.pdf", jpeg, img.width_px, img.height_px, 600);
}

/// This RIP making the same 1-bit CMYK separations from the same JPEG (decoding it included: the
/// file is decoded on its own thread while the rows already decoded are coloured and screened).
Status rip_ghostscript_image(const RipBenchOptions& o, const std::filesystem::path& dir, const FigureSink& emit) {
  const auto t0 = Clock::now();
  RipSettings s = bench_settings(o);
  auto src = ImageFileSource::open(dir / "image.jpg", 2 * s.band_rows);
  if (!src) return std::unexpected(src.error());
  device::PrinterModel printer;
  printer.bits_per_pixel = 1;
  s.drop_levels = 2;
  s.separations.screened_tiff = dir / "rip_sep.tif";
  s.separations.one_file_per_ink = true;
  auto st = run_rip(**src, printer, s, discard);
  if (!st) return std::unexpected(st.error());
  emit("rip_1bit_seconds", num(std::chrono::duration<double>(Clock::now() - t0).count(), 2));
  emit("rip_1bit_area_m2", num(st->area_m2, 4));
  emit("rip_1bit_rip_seconds", num(st->wall_s, 2));
  emit("rip_1bit_separations_seconds", num(st->separations_s, 2));
  return {};
}

/// The job of `o.renderer` across the roll width.
Result<BenchJob> make_bench_job(const RipBenchOptions& o) {
  const double width_mm = o.width_m * 1000;
  const int build_threads = o.threads > 0 ? o.threads : 2;
  if (o.renderer == "panels") return make_panel_bench_job(width_mm, build_threads);
  if (o.renderer == "garment") return make_garment_bench_job(width_mm, build_threads);
  if (o.renderer == "textured") return make_textured_bench_job(width_mm);
  return fail(ErrorCode::kInvalidArgument, "bench: renderer '" + o.renderer + "' is not panels, garment or textured");
}

double figure(const ChildRun& run, const std::string& key) {
  for (const auto& [k, v] : run.figures)
    if (k == key) return std::stod(v);
  return 0;
}

}  // namespace

Status run_rip_bench(const RipBenchOptions& o, const FigureSink& emit) {
  if (!(o.width_m > 0 && o.width_m <= 1.65 && o.length_m > 0))
    return fail(ErrorCode::kInvalidArgument, fmt::format("bench: width {} m (up to 1.65) and length {} m must be positive",
                                                         o.width_m, o.length_m));
  // The job is built once, before any child is forked: children share it copy-on-write.
  Result<BenchJob> job = make_bench_job(o);
  if (!job) return std::unexpected(job.error());
  emit("renderer", job->description);
  emit("coverage", num(job->block.utilisation, 3));
  emit("dpi", "600x600");
  emit("inks", "4");
  emit("bits_per_pixel", "2");
  emit("width_m", num(o.width_m, 2));
  emit("length_m", num(o.length_m, 2));
  emit("passes", std::to_string(o.passes));

  auto whole = run_in_child([&](const FigureSink& e) { return measure_whole(o, *job, e); });
  if (!whole) return std::unexpected(whole.error());
  for (const auto& [k, v] : whole->figures) emit(k, v);
  emit("cpu_m2_per_hour", num(figure(*whole, "area_m2") / (whole->cpu_s / figure(*whole, "threads")) * kSecondsPerHour));
  emit("peak_rss_mb", num(whole->peak_rss_mb));

  auto after = run_in_child([&](const FigureSink& e) { return measure_after_render(o, *job, e); });
  if (!after) return std::unexpected(after.error());
  for (const auto& [k, v] : after->figures) emit(k, v);

  std::vector<double> rss;
  for (double len : o.rss_lengths_m) {
    double mb = whole->peak_rss_mb;
    if (len != o.length_m) {
      RipBenchOptions probe = o;
      probe.length_m = len;
      auto run = run_in_child([&](const FigureSink&) { return measure_whole(probe, *job, [](std::string_view, std::string_view) {}); });
      if (!run) return std::unexpected(run.error());
      mb = run->peak_rss_mb;
    }
    rss.push_back(mb);
    emit(fmt::format("peak_rss_mb_{}m", num(len, len == std::floor(len) ? 0 : 1)), num(mb));
  }
  if (rss.size() >= 2) emit("rss_growth_pct", num((rss.back() / rss.front() - 1) * 100));

  if (o.vs_ghostscript) {
    const std::string gs = find_ghostscript();
    if (gs.empty()) {
      emit("ghostscript_m2_per_hour", "unavailable");
      return {};
    }
    std::filesystem::path dir = o.work_dir.empty()
                                    ? std::filesystem::temp_directory_path() / fmt::format("tp-bench-rip-{}", ::getpid())
                                    : o.work_dir;
    std::filesystem::create_directories(dir);
    auto prep = run_in_child([&](const FigureSink& e) { return prepare_ghostscript_input(o, dir, e); });
    if (!prep) return std::unexpected(prep.error());
    for (const auto& [k, v] : prep->figures) emit(k, v);
    auto gs_s = run_ghostscript(gs, dir);
    if (!gs_s) return std::unexpected(gs_s.error());
    auto ours = run_in_child([&](const FigureSink& e) { return rip_ghostscript_image(o, dir, e); });
    if (!ours) return std::unexpected(ours.error());
    for (const auto& [k, v] : ours->figures) emit(k, v);
    const double area = figure(*ours, "rip_1bit_area_m2"), rip_s = figure(*ours, "rip_1bit_seconds");
    emit("ghostscript_seconds", num(*gs_s, 2));
    emit("ghostscript_m2_per_hour", num(area / *gs_s * kSecondsPerHour));
    emit("rip_1bit_m2_per_hour", num(area / rip_s * kSecondsPerHour));
    emit("ratio_vs_ghostscript", num(*gs_s / rip_s, 2));
    if (o.work_dir.empty()) std::filesystem::remove_all(dir);
  }
  return {};
}

}  // namespace tp::rip
