// host/pipeline/stage_print.cpp: the print stage: the roll RIPped band by band and each swath
// streamed to the printer as soon as it is complete, with cutter cues at marker ends and notch
// marks at notch positions; every printed swath becomes the job's resume checkpoint, and the
// session decides where a resumed job goes on from what the printer holds.
#include <algorithm>
#include <cmath>
#include <optional>

#include "device/firmware/print_timing.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_steps.h"
#include "host/pipeline/internal/printed_seams.h"
#include "host/pipeline/printer_check.h"
#include "host/pipeline/printer_model.h"
#include "host/session/print_session.h"
#include "rip/job/rip_job.h"

namespace tp::host::internal {

namespace {

rip::RipSettings rip_settings(const PipelineState& ps, const device::PrinterModel& printer) {
  const PrintSpec& p = ps.job.print;
  rip::RipSettings s;
  s.passes = p.passes;
  s.bidirectional = p.bidirectional;
  s.screen = p.screen == "error-diffusion" ? rip::ScreenKind::kErrorDiffusion : rip::ScreenKind::kBlueNoise;
  s.drop_levels = p.levels == 2 ? 2 : 0;
  if (p.icc_profile) s.profile_path = *p.icc_profile;
  if (p.calibration_profile) s.calibration_profile = *p.calibration_profile;
  s.ink_limit_percent = p.ink_limit_pct;
  if (p.calibration_set) {
    // The set's curves per ink of this printer, and its measured ink limit if that is lower.
    std::vector<std::string> inks;
    for (const auto& ink : printer.inks) inks.push_back(ink.name);
    s.linearisation = linearisation_for(*p.calibration_set, inks);
    if (p.calibration_set->ink_limit_percent > 0)
      s.ink_limit_percent = std::min(s.ink_limit_percent, p.calibration_set->ink_limit_percent);
  }
  s.device_inks = p.device_inks;
  s.first_swath_index = static_cast<std::uint32_t>(std::max<std::int64_t>(0, ps.options.resume_after_swath + 1));
  if (p.separations_tiff) s.separations.screened_tiff = ps.options.out_dir / "separations.tif";
  s.mirror_print = p.transfer == "sublimation";
  return s;
}

// A point at arc length `s_mm` along an edge polyline.
geometry::Vec2 point_on_edge(const geometry::Edge& e, double s_mm) {
  for (size_t i = 1; i < e.points_mm.size(); ++i) {
    double len = geometry::norm(e.points_mm[i] - e.points_mm[i - 1]);
    if (s_mm <= len || i + 1 == e.points_mm.size()) {
      double t = len > 0 ? std::clamp(s_mm / len, 0.0, 1.0) : 0;
      return e.points_mm[i - 1] + (e.points_mm[i] - e.points_mm[i - 1]) * t;
    }
    s_mm -= len;
  }
  return e.points_mm.front();
}

struct Cue {
  device::CueKind kind;
  std::int64_t y_um;
  std::int32_t x_um;
};

// Cut cues at the end of each marker, notch marks where each placed piece has a notch.
std::vector<Cue> roll_cues(const PipelineState& ps) {
  std::vector<Cue> cues;
  for (const auto& pl : ps.roll.placements) {
    const geometry::Piece& piece = ps.pattern.pieces[static_cast<size_t>(pl.piece)];
    const geometry::Affine2 to_roll = pl.piece_to_roll();
    for (const auto& n : piece.notches) {
      if (n.edge < 0 || n.edge >= static_cast<int>(piece.edges.size())) continue;
      geometry::Vec2 p = to_roll.apply(point_on_edge(piece.edges[static_cast<size_t>(n.edge)], n.position_mm));
      cues.push_back({device::CueKind::kNotch, std::llround(p.y * 1000), static_cast<std::int32_t>(std::lround(p.x * 1000))});
    }
  }
  for (size_t k = 0; k < ps.markers.size(); ++k)
    cues.push_back({device::CueKind::kCut, std::llround((ps.marker_start_mm[k] + ps.markers[k].length_mm) * 1000), 0});
  std::sort(cues.begin(), cues.end(), [](const Cue& a, const Cue& b) { return a.y_um < b.y_um; });
  return cues;
}

// Counts per named ink channel, in the printer model's ink order.
template <class Counts>
nlohmann::json per_ink(const Counts& counts, const device::PrinterModel& model) {
  nlohmann::json out = nlohmann::json::object();
  for (size_t c = 0; c < counts.size() && c < model.inks.size(); ++c) out[model.inks[c].name] = counts[c];
  return out;
}

nlohmann::json rip_json(const rip::RipStats& st, const device::PrinterModel& model) {
  std::vector<std::uint64_t> drops;
  for (const auto& d : st.drops) drops.push_back(d[1] + d[2] + d[3]);
  return {{"width_px", st.width_px},
          {"height_px", st.height_px},
          {"area_m2", st.area_m2},
          {"swaths", st.swaths},
          {"compression_ratio", st.compression_ratio},
          {"drops_per_ink", per_ink(drops, model)},
          {"threads", st.threads},
          {"wall_s", st.wall_s},
          {"colour_table_mib", static_cast<double>(st.colour_table_bytes) / (1 << 20)}};
}

// Print time and swath count before printing, from the marker and the printer model: the pass
// plan advances the fabric nozzles/passes rows per swath (plus passes - 1 swaths to enter and
// leave the head), each swath crosses the marker's width, each feed moves one advance.
nlohmann::json print_estimate(const PipelineState& ps, const device::PrinterModel& model) {
  const double rows = std::ceil(ps.roll.length_mm * model.dpi_y / 25.4);
  const int passes = std::max(1, ps.job.print.passes);
  const double advance_rows = std::max(1.0, static_cast<double>(model.nozzles_per_ink) * model.nozzle_pitch_rows / passes);
  const double swaths = std::ceil(rows / advance_rows) + passes - 1;
  device::SwathHeader h;
  h.width_px = static_cast<std::uint32_t>(std::lround(ps.roll.width_mm * model.dpi_x / 25.4));
  const auto feed_um = static_cast<std::int64_t>(std::llround(advance_rows * 25.4e3 / model.dpi_y));
  const double seconds = swaths * (device::pass_time_s(model, h) + device::feed_time_s(model, feed_um));
  return {{"print_time_s", seconds}, {"fabric_length_mm", ps.roll.length_mm}, {"swaths", static_cast<std::int64_t>(swaths)}};
}

// Drops and ink volume per named channel from the RIP's per-level drop counts.
nlohmann::json ink_json(const rip::RipStats& st, const device::PrinterModel& model) {
  nlohmann::json drops = nlohmann::json::object(), ml = nlohmann::json::object();
  for (size_t c = 0; c < st.drops.size() && c < model.inks.size(); ++c) {
    std::uint64_t n = 0;
    double pl = 0;
    for (size_t level = 1; level < st.drops[c].size(); ++level) {
      n += st.drops[c][level];
      const double v = level - 1 < model.drop_volume_pl.size() ? model.drop_volume_pl[level - 1] : 0;
      pl += static_cast<double>(st.drops[c][level]) * v;
    }
    drops[model.inks[c].name] = n;
    ml[model.inks[c].name] = pl * 1e-9;  // 1 pL = 1e-9 ml
  }
  return {{"drops", drops}, {"ml", ml}};
}

}  // namespace

Status stage_print(PipelineState& ps) {
  const PrinterChoice printer = effective_printer(ps.job.print.printer, ps.options.printer_override);
  auto model = job_printer_model(ps.job);
  if (!model) return fail(model.error());
  rip::RipSettings settings = rip_settings(ps, *model);
  auto swath_plan = SwathPlan::open(ps, *model, settings.first_swath_index);
  if (!swath_plan) return fail(swath_plan.error());
  ps.report["estimate"] = print_estimate(ps, *model);

  // Without a printer (kNone) the RIP still runs in full; its swaths are counted and dropped.
  std::unique_ptr<PrintSession> session;
  std::uint32_t acked = 0;
  if (printer != PrinterChoice::kNone) {
    PrinterConfig cfg;
    cfg.printer = printer;
    auto s = PrintSession::open(cfg);
    if (!s) return fail(s.error());
    session = std::move(*s);
    if (auto st = check_printer(*model, session->printer()); !st) return st;
    session->on_swath_acked([&](std::uint32_t index) { acked = std::max(acked, index + 1); });
    session->on_swath_printed([&](std::uint32_t index, std::int64_t) {
      if (ps.options.on_checkpoint) ps.options.on_checkpoint(index);
    });
    if (ps.options.on_printer) {
      PrintSession* live = session.get();
      session->on_status([&ps, live](const device::StatusMsg& st) {
        ps.options.on_printer(PrinterLive{live->printer(), st, std::nullopt});
      });
      session->on_cue_fired([&ps, live](const CueRecord& cue) {
        const device::StatusMsg* st = live->printer_status();
        ps.options.on_printer(PrinterLive{live->printer(), st ? *st : device::StatusMsg{}, cue});
      });
    }
    JobStart start;
    start.job_id = static_cast<std::uint64_t>(ps.options.job_id);
    start.name = ps.job.name;
    start.first_swath = settings.first_swath_index;
    start.fabric_width_px = static_cast<std::uint32_t>(std::lround(ps.roll.width_mm / 25.4 * model->dpi_x));
    ps.print_began = std::filesystem::file_time_type::clock::now();
    if (auto st = session->begin_job(start); !st) return st;
    // A job the printer completed while the host was away is not printed again: its record is
    // from then, before this run.
    if (session->finished_on_printer()) ps.print_began.reset();
    // The printer's record decides where the job goes on (it may have printed past the checkpoint).
    settings.first_swath_index = session->resume_swath();
    for (const Cue& c : roll_cues(ps))
      if (auto st = session->queue_cue(c.kind, c.y_um, c.x_um); !st) return st;
  }

  // Swaths go to the printer as the RIP completes them. A printer that fails the job (a fault such
  // as a head strike or media jam, an unplug that lasts) stops the RIP; its own error is what the
  // job reports, so the operator reads a printer fault, not a RIP error.
  std::optional<Error> printer_error;
  auto sink = [&](device::Swath&& swath) -> rip::Status {
    // Nothing reaches the printer that the job's stored swath plan does not hold.
    if (auto st = swath_plan->check(swath); !st) return rip::fail(rip::ErrorCode::kSwath, st.error().message);
    if (!session) return {};
    if (auto st = session->send_swath(swath, ps.cancel); !st) {
      if (st.error().code == ErrorCode::kCancelled) return rip::fail(rip::ErrorCode::kCancelled, st.error().message);
      printer_error = st.error();
      return rip::fail(rip::ErrorCode::kSwath, st.error().message);
    }
    return {};
  };
  // Progress: with a printer the print stage counts acknowledged swaths (run_job's checkpoint);
  // without one the RIP's bands are the stage's work.
  rip::ProgressCallback rip_progress;
  if (!session && ps.options.on_progress)
    rip_progress = [&ps](const rip::RipProgress& p) {
      if (p.rows_total <= 0) return;
      const double fraction = std::min(1.0, static_cast<double>(p.rows_done) / static_cast<double>(p.rows_total));
      ps.options.on_progress(Stage::kPrint, fraction,
                             "rip band " + std::to_string(p.band) + ": rows " + std::to_string(p.rows_done) + " of " +
                                 std::to_string(p.rows_total));
    };
  // The roll as printed: the plan, unless a test misplaces a piece (RunOptions::misplace_for_test).
  auto printed = printed_roll(ps);
  if (!printed) return fail(printed.error());
  auto stats = rip::rip_marker(*printed, *ps.renderer, *model, settings, sink, rip_progress, ps.cancel);
  if (!stats) {
    if (session) (void)session->abort_job(stats.error().message);  // a no-op once the session ended it
    if (printer_error) return fail(*printer_error);
    bool cancelled = stats.error().code == rip::ErrorCode::kCancelled || ps.cancel.cancelled();
    return fail(cancelled ? ErrorCode::kCancelled : ErrorCode::kPipeline, stats.error().message);
  }
  ps.report["rip"] = rip_json(*stats, *model);
  if (auto st = swath_plan->finish(stats->swaths); !st) return st;
  ps.report["ink"] = ink_json(*stats, *model);
  ps.report["measured"] = {{"print_time_s", nullptr}, {"fabric_length_mm", nullptr}, {"swaths", stats->swaths}};

  nlohmann::json print = {{"printer", std::string(to_string(printer))},
                          {"swaths_total", stats->swaths},
                          {"swaths_sent", stats->swaths_sent},
                          {"swaths_acked", session ? nlohmann::json(acked) : nlohmann::json(nullptr)}};
  if (session) {
    // Feed the end of the roll past the cutter so the last cut cue fires.
    const std::int64_t end_um = std::llround(ps.roll.length_mm * 1000);
    const std::int64_t fed_to_um = session->fabric_after_swaths_um();
    auto result = session->end_job(static_cast<std::uint32_t>(std::max<std::int64_t>(0, end_um - fed_to_um)), ps.cancel);
    if (!result) return fail(result.error());
    const SessionStats& ss = result->stats;
    print["swaths_sent"] = ss.swaths_sent;
    print["swaths_acked"] = ss.swaths_acked;
    print["swaths_skipped_resume"] = ss.swaths_skipped;
    print["reconnects"] = ss.reconnects;
    print["resumed_from_swath"] = session->resume_swath() - ss.swaths_sent;
    print["reattached"] = ss.reattached;
    print["lost_job_resumes"] = ss.lost_job_resumes;
    print["printer_swaths_printed"] = result->report.swaths_printed;
    print["feed_travel_mm"] = static_cast<double>(result->report.feed_travel_um) / 1000.0;
    print["print_time_s"] = static_cast<double>(result->report.print_time_us) / 1e6;
    print["cues_fired"] = result->report.cues_fired;
    print["drops_per_ink"] = per_ink(result->report.drops_per_ink, *model);
    print["outcome"] = std::string(device::to_string(result->report.outcome));
    nlohmann::json cues = nlohmann::json::array();
    for (const auto& c : result->cues)
      cues.push_back({{"kind", std::string(device::to_string(c.kind))},
                      {"position_mm", static_cast<double>(c.position_um) / 1000.0},
                      {"fired", c.fired},
                      {"fired_at_mm", c.fired ? nlohmann::json(static_cast<double>(c.fired_at_um) / 1000.0) : nlohmann::json(nullptr)}});
    print["cues"] = cues;
    ps.report["measured"]["print_time_s"] = print["print_time_s"];
    ps.report["measured"]["fabric_length_mm"] = static_cast<double>(result->report.feed_travel_um) / 1000.0;
  }
  ps.report["print"] = print;
  return {};
}

}  // namespace tp::host::internal
