// host/pipeline/stage_marker.cpp: the marker stage: cut outlines nested on the roll under the
// job's grain, mirror, gap and defect rules; markers laid end to end; marker.png.
#include <algorithm>
#include <cmath>
#include <optional>

#include <spdlog/fmt/fmt.h>

#include "geometry/nesting/nest_pieces.h"
#include "host/pipeline/internal/budget_ticker.h"
#include "host/pipeline/internal/output_files.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_steps.h"
#include "host/pipeline/marker_nesting.h"
#include "rip/image/image_io.h"
#include "rip/render/marker_preview.h"

namespace tp::host::internal {

Status stage_marker(PipelineState& ps) {
  const MarkerSpec& m = ps.job.marker;
  std::vector<geometry::NestItem> items = marker_nest_items(ps.pattern, *ps.renderer, m);
  double piece_area_mm2 = 0;
  for (const geometry::NestItem& item : items) piece_area_mm2 += std::abs(geometry::signed_area(item.outline_mm));
  geometry::NestOptions opt = marker_nest_options(m);
  geometry::NestStats nest_stats;
  auto stored = find_plan_markers(ps, items, opt);
  if (!stored) return fail(stored.error());
  if (*stored) {
    // The markers the job's plan recorded: never nested twice (the fabric printed follows them).
    ps.markers = std::move(**stored);
    ps.stage_reused = true;
  } else {
    // Progress: an iteration budget reports the iterations done through the nester's work hook,
    // on this thread. A time budget has no such count, but tells how far it is: a timer thread
    // reports elapsed / budget while the pipeline thread nests (it makes no other calls meanwhile,
    // and the thread is joined before the stage ends, so calls never overlap).
    std::optional<BudgetTicker> ticker;
    if (ps.options.on_progress && opt.time_limit_s > 0)
      ticker.emplace(ps.options.on_progress, Stage::kMarker, opt.time_limit_s);
    if (ps.options.on_progress && opt.work_limit > 0 && opt.time_limit_s == 0)
      opt.on_work = [&ps](std::uint64_t done, std::uint64_t total) {
        const double fraction = std::min(0.99, static_cast<double>(done) / static_cast<double>(total));
        ps.options.on_progress(Stage::kMarker, fraction, fmt::format("{} of {} iterations", done, total));
      };
    auto markers = geometry::nest_pieces(items, opt, ps.cancel, &nest_stats);
    ticker.reset();
    if (!markers) {
      auto code = markers.error().code == geometry::ErrorCode::kCancelled ? ErrorCode::kCancelled : ErrorCode::kPipeline;
      return fail(code, markers.error().message);
    }
    ps.markers = std::move(*markers);
    if (auto st = save_plan_markers(ps, items, opt, ps.markers, nest_stats); !st) return st;
  }

  // One roll: each marker starts where the previous one ends.
  ps.roll = {};
  ps.roll.width_mm = m.fabric_width_mm;
  ps.marker_start_mm.clear();
  nlohmann::json list = nlohmann::json::array();
  for (size_t k = 0; k < ps.markers.size(); ++k) {
    const geometry::Marker& mk = ps.markers[k];
    ps.marker_start_mm.push_back(ps.roll.length_mm);
    for (auto p : mk.placements) {
      p.offset_mm.y += ps.roll.length_mm;
      ps.roll.placements.push_back(p);
    }
    list.push_back({{"start_mm", ps.roll.length_mm}, {"length_mm", mk.length_mm},
                    {"pieces", mk.placements.size()}, {"utilisation", mk.utilisation}});
    if (k < nest_stats.iterations.size()) list.back()["search_iterations"] = nest_stats.iterations[k];
    ps.roll.length_mm += mk.length_mm;
  }
  ps.roll.utilisation = ps.roll.length_mm > 0 ? piece_area_mm2 / (ps.roll.width_mm * ps.roll.length_mm) : 0;
  ps.report["marker"] = {{"fabric_width_mm", ps.roll.width_mm},
                         {"length_mm", ps.roll.length_mm},
                         {"utilisation", ps.roll.utilisation},
                         {"budget", m.iterations > 0 ? nlohmann::json{{"iterations", m.iterations}}
                                                     : nlohmann::json{{"time_limit_s", m.time_limit_s}}},
                         {"source", ps.stage_reused ? "plan" : "nested"},
                         {"markers", list}};
  ps.report["fabric_length_mm"] = ps.roll.length_mm;

  auto preview = rip::render_marker_preview(ps.roll, *ps.renderer, ps.job.print.preview_dpi);
  if (!preview) return fail(ErrorCode::kPipeline, "marker.png: " + preview.error().message);
  if (auto st = write_png_checked(ps.options.out_dir / "marker.png", *preview, rip::PngChannels::kRgbOverWhite,
                                  ps.job.print.preview_dpi);
      !st)
    return st;
  return {};
}

}  // namespace tp::host::internal
