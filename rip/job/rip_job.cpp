// rip/job/rip_job.cpp: the band loop of a RIP job: validate, build colour/screen/weave, then band by band
// render+colour+screen, write separations, emit finished swaths, report progress, honour cancel.
#include "rip/job/rip_job.h"

#include <chrono>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "device/swath/packbits.h"

#include "geometry/common/thread_pool.h"
#include "rip/common/internal/log.h"
#include "rip/job/internal/band_stage.h"
#include "rip/job/internal/screened_window.h"
#include "rip/job/internal/separation_output.h"
#include "rip/job/internal/swath_assembler.h"
#include "rip/render/marker_source.h"

namespace tp::rip {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kMmPerInch = 25.4;
constexpr int kMaxBandRows = 4096;
/// From this many pixels (about 0.09 m2 at 600 dpi) the colour table of every 8-bit colour is
/// built: its 0.04-0.09 s (measured on 2 cores) is then under 5 % of the job, and per-pixel colour
/// costs one lookup.
constexpr double kDirectTableMinPixels = 50e6;

Status validate(const BandSource& source, const device::PrinterModel& printer, const RipSettings& s) {
  if (s.band_rows < kRenderTileRows || s.band_rows > kMaxBandRows || s.band_rows % kRenderTileRows != 0)
    return fail(ErrorCode::kInvalidArgument, fmt::format("settings.band_rows {} must be a multiple of {} in {}..{}",
                                                         s.band_rows, kRenderTileRows, kRenderTileRows, kMaxBandRows));
  if (printer.inks.empty() || printer.inks.size() > 15)
    return fail(ErrorCode::kInvalidArgument, fmt::format("printer '{}': {} inks (1..15 supported)", printer.name,
                                                         printer.inks.size()));
  if (printer.bits_per_pixel != 1 && printer.bits_per_pixel != 2)
    return fail(ErrorCode::kInvalidArgument, fmt::format("printer '{}': bits_per_pixel {} (1 or 2 supported)",
                                                         printer.name, printer.bits_per_pixel));
  if (printer.dpi_x <= 0 || printer.dpi_y <= 0)
    return fail(ErrorCode::kInvalidArgument, fmt::format("printer '{}': resolution {}x{} dpi", printer.name,
                                                         printer.dpi_x, printer.dpi_y));
  const int max_levels = 1 << printer.bits_per_pixel;
  if (s.drop_levels != 0 && (s.drop_levels < 2 || s.drop_levels > max_levels))
    return fail(ErrorCode::kInvalidArgument, fmt::format("settings.drop_levels {} must be 0 or 2..{}", s.drop_levels,
                                                         max_levels));
  const double max_width_px = std::floor(printer.print_width_mm * printer.dpi_x / kMmPerInch + 0.5);
  if (source.width_px() <= 0 || source.width_px() > max_width_px)
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("print is {} px wide; printer '{}' prints at most {} px ({} mm at {} dpi)",
                            source.width_px(), printer.name, max_width_px, printer.print_width_mm, printer.dpi_x));
  if (source.height_px() <= 0)
    return fail(ErrorCode::kInvalidArgument, fmt::format("print has {} rows", source.height_px()));
  return {};
}

}  // namespace

Result<RipStats> run_rip(const BandSource& source, const device::PrinterModel& printer, const RipSettings& settings,
                         const SwathSink& sink, const ProgressCallback& progress, const geometry::CancelToken& cancel) {
  const auto t_start = Clock::now();
  if (auto ok = validate(source, printer, settings); !ok) return std::unexpected(ok.error());

  std::vector<std::string> inks;
  for (const auto& ink : printer.inks) inks.push_back(ink.name);
  InkConverterSettings cs;
  cs.profile_path = settings.profile_path;
  cs.ink_names = inks;
  cs.intent = settings.intent;
  cs.calibration_profile = settings.calibration_profile;
  cs.ink_limit_percent = settings.ink_limit_percent;
  cs.linearisation = settings.linearisation;
  cs.device_inks = settings.device_inks;
  // A job of many pixels repays building the table of every colour.
  cs.direct_table = static_cast<double>(source.width_px()) * static_cast<double>(source.height_px()) >= kDirectTableMinPixels;
  auto ink = InkConverter::create(cs);
  if (!ink) return std::unexpected(ink.error());

  ScreenSetup ss;
  ss.kind = settings.screen;
  ss.channels = static_cast<int>(inks.size());
  ss.bits_per_pixel = printer.bits_per_pixel;
  ss.levels = settings.drop_levels ? settings.drop_levels : 1 << printer.bits_per_pixel;
  ss.width_px = source.width_px();
  auto screen = make_screen(ss);
  if (!screen) return std::unexpected(screen.error());

  auto plan = make_pass_plan(printer, settings.passes);
  if (!plan) return std::unexpected(plan.error());

  ThreadPool pool(settings.threads);
  const std::int64_t height = source.height_px();
  // The window holds a head height of rows plus one band: the oldest unfinished pass's rows and
  // the band being screened.
  const int slots = (plan->nozzles_used - 1) * plan->nozzle_pitch_rows + 1 + settings.band_rows;
  ScreenedWindow window(ss.channels, packed_row_bytes(ss), slots);

  std::unique_ptr<SeparationOutput> separations;
  if (!settings.separations.contone_tiff.empty() || !settings.separations.screened_tiff.empty()) {
    auto so = SeparationOutput::open(settings.separations, inks, ss.width_px, height, ss.bits_per_pixel,
                                     printer.dpi_x, printer.dpi_y);
    if (!so) return std::unexpected(so.error());
    separations = std::move(*so);
  }
  BandStage stage(source, *ink, **screen, ss, window, settings.band_rows, pool.size(),
                  separations && separations->wants_contone());
  SwathAssembler swaths(*plan, printer, settings, ss.width_px, height, ss.bits_per_pixel, window, pool.size());

  RipStats stats;
  stats.width_px = ss.width_px;
  stats.height_px = height;
  stats.area_m2 = (ss.width_px * kMmPerInch / printer.dpi_x) * (static_cast<double>(height) * kMmPerInch / printer.dpi_y) * 1e-6;
  stats.plan = *plan;
  stats.threads = pool.size();
  // 2^24 colours, four inks packed in 32 bits (InkConverterSettings::direct_table).
  if (cs.direct_table && inks.size() <= 4) stats.colour_table_bytes = std::uint64_t{4} << 24;

  RipProgress prog;
  prog.rows_total = height;
  for (std::int64_t y0 = 0; y0 < height; y0 += settings.band_rows) {
    if (cancel.cancelled())
      return fail(ErrorCode::kCancelled, fmt::format("RIP cancelled at fabric row {} of {}", y0, height));
    const int rows = static_cast<int>(std::min<std::int64_t>(settings.band_rows, height - y0));
    stage.run(pool, y0, rows);
    if (auto s = source.status(); !s) return fail(s.error().with_context(fmt::format("RIP at fabric row {}", y0)));
    if (separations) {
      auto t0 = Clock::now();
      auto s = separations->write_band(pool, stage, window, y0, rows);
      stats.separations_s += std::chrono::duration<double>(Clock::now() - t0).count();
      if (!s) return std::unexpected(s.error());
    }
    auto s = swaths.emit_ready(y0 + rows, pool, sink, stats);
    if (!s) return std::unexpected(s.error());
    ++prog.band;
    prog.rows_done = y0 + rows;
    prog.fabric_y_mm = static_cast<double>(prog.rows_done) * kMmPerInch / printer.dpi_y;
    prog.swaths_done = stats.swaths;
    if (progress) progress(prog);
  }
  if (separations) {
    auto s = separations->close();
    if (!s) return std::unexpected(s.error());
  }

  stats.drops.assign(static_cast<size_t>(ss.channels), {});
  for (const StageTally& t : stage.tallies()) {
    stats.render_cpu_s += t.render_s;
    stats.colour_cpu_s += t.colour_s;
    stats.screen_cpu_s += t.screen_s;
    for (int c = 0; c < ss.channels; ++c)
      for (int k = 0; k < 4; ++k) stats.drops[static_cast<size_t>(c)][static_cast<size_t>(k)] += t.drops[static_cast<size_t>(c)][static_cast<size_t>(k)];
  }
  stats.compression_ratio = stats.compressed_bytes ? static_cast<double>(stats.raw_bytes) / stats.compressed_bytes : 1.0;
  stats.wall_s = std::chrono::duration<double>(Clock::now() - t_start).count();
  logger().info("RIP {}x{} px ({:.2f} m2): {} swaths ({} sent), compression {:.2f}, {:.1f} s", stats.width_px,
                stats.height_px, stats.area_m2, stats.swaths, stats.swaths_sent, stats.compression_ratio, stats.wall_s);
  return stats;
}

geometry::Marker mirrored_across_width(const geometry::Marker& marker, double dpi_x) {
  // About the raster's own width, so printer column c shows what column (width - 1 - c) would.
  const double width_mm = std::ceil(marker.width_mm * dpi_x / 25.4) * 25.4 / dpi_x;
  geometry::Marker out = marker;
  for (geometry::PiecePlacement& pl : out.placements) {
    // x -> W - x after translate * rotate(theta) * mirror: translate(W - ox, oy) * rotate(-theta) * !mirror.
    pl.offset_mm.x = width_mm - pl.offset_mm.x;
    pl.rotation_deg = -pl.rotation_deg;
    pl.mirrored = !pl.mirrored;
  }
  return out;
}

Result<RipStats> rip_marker(const geometry::Marker& marker, const geometry::PieceRenderer& renderer,
                            const device::PrinterModel& printer, const RipSettings& settings, const SwathSink& sink,
                            const ProgressCallback& progress, const geometry::CancelToken& cancel) {
  // Printer column 0 is at roll x = 0 unless the carriage starts over the right selvedge; a
  // sublimation transfer prints the mirror image. Either turns the rows round (docs/roll-frame.md).
  const bool mirror = settings.mirror_print != (printer.carriage_origin == device::CarriageOrigin::kRight);
  auto source = MarkerSource::create(mirror ? mirrored_across_width(marker, printer.dpi_x) : marker, renderer,
                                     printer.dpi_x, printer.dpi_y);
  if (!source) return std::unexpected(source.error());
  return run_rip(**source, printer, settings, sink, progress, cancel);
}

Result<std::vector<std::uint8_t>> decode_swath_data(const device::Swath& swath) {
  const device::SwathHeader& h = swath.header;
  const std::uint64_t expect = static_cast<std::uint64_t>(device::swath_row_bytes(h)) * h.rows * h.channels;
  if (expect != h.raw_bytes)
    return fail(ErrorCode::kSwath, fmt::format("swath {}: raw_bytes {} but {} rows x {} inks x {} bytes = {}", h.index,
                                               h.raw_bytes, h.rows, h.channels, device::swath_row_bytes(h), expect));
  switch (h.compression) {
    case device::SwathCompression::kNone:
      if (swath.data.size() != h.raw_bytes)
        return fail(ErrorCode::kSwath, fmt::format("swath {}: {} data bytes, expected {}", h.index, swath.data.size(),
                                                   h.raw_bytes));
      return swath.data;
    case device::SwathCompression::kPackBits: {
      std::vector<std::uint8_t> raw;
      if (auto d = device::packbits_decode(swath.data, h.raw_bytes, raw); !d)
        return fail(ErrorCode::kSwath, fmt::format("swath {}: {}", h.index, d.error().message));
      return raw;
    }
  }
  return fail(ErrorCode::kSwath, fmt::format("swath {}: unknown compression", h.index));
}

}  // namespace tp::rip
