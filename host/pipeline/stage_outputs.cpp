// host/pipeline/stage_outputs.cpp: the outputs stage: each piece as a PNG, seam and allowance
// continuity measured on the rendered contone raster, and the cut files.
#include <cctype>
#include <filesystem>
#include <set>

#include "geometry/continuity/continuity.h"
#include "geometry/cutfile/cut_job.h"
#include "geometry/cutfile/dxf_aama_writer.h"
#include "geometry/cutfile/svg_writer.h"
#include "geometry/design/render_piece_image.h"
#include "geometry/garment/flat_pieces.h"
#include "host/common/atomic_file.h"
#include "host/pipeline/garment_files.h"
#include "host/pipeline/internal/gamut_report.h"
#include "host/pipeline/internal/order_run.h"
#include "host/pipeline/internal/output_files.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/printed_seams.h"
#include "rip/image/image_io.h"

namespace tp::host::internal {

// Print previews: the pieces' prints at about 1.2 px/mm, finer than a 600 x 900 preview of a body.
constexpr double kPrintPreviewDpi = 30;

namespace {

// Piece names become file names: keep letters, digits, '-', '_' and '.'.
std::string file_stem(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return out.empty() ? "piece" : out;
}

// Colour differences, null when nothing was sampled (no seam or allowance to measure).
nlohmann::json stats_json(const geometry::DeltaEStats& s) {
  if (s.samples == 0) return {{"samples", 0}, {"de00_mean", nullptr}, {"de00_p95", nullptr}, {"de00_max", nullptr}};
  return {{"samples", s.samples}, {"de00_mean", s.mean}, {"de00_p95", s.p95}, {"de00_max", s.max}};
}

}  // namespace

/// Resolution at which seam continuity is measured for the report.
constexpr double kContinuityDpi = 150;

Status stage_outputs(PipelineState& ps) {
  const auto& out = ps.options.out_dir;
  std::error_code ec;
  std::filesystem::create_directories(out / "pieces", ec);
  nlohmann::json pieces = nlohmann::json::array();
  for (int i = 0; i < ps.renderer->piece_count(); ++i) {
    if (ps.cancel.cancelled()) return fail(ErrorCode::kCancelled, "job cancelled");
    auto img = geometry::render_piece_image(*ps.renderer, i, ps.job.print.preview_dpi);
    std::string name = "pieces/" + file_stem(ps.pattern.pieces[static_cast<size_t>(i)].name) + ".png";
    if (auto st = write_png_checked(out / name, img.image, rip::PngChannels::kRgba, ps.job.print.preview_dpi); !st)
      return st;
    pieces.push_back(name);
  }
  ps.report["files"] = {{"marker", "marker.png"}, {"pieces", pieces}};

  // The 3D garment again, now with its print: the pieces packed into one texture, OBJ + MTL.
  if (ps.garment_is_3d && ps.garment) {
    // Without the pieces printed flat (joined to no other piece): they are not part of it.
    const std::vector<int> flat = ps.body ? geometry::unjoined_pieces(ps.pattern) : std::vector<int>{};
    const geometry::Garment worn = flat.empty() ? *ps.garment : geometry::garment_without(*ps.garment, flat);
    auto tex = write_textured_garment(out, "garment", ps.pattern, worn, *ps.renderer, ps.job.print.preview_dpi);
    if (!tex) return fail(tex.error());
    auto& files = ps.report["garment"]["files"];
    files["obj"] = tex->obj;
    files["mtl"] = tex->mtl;
    files["texture"] = tex->texture;
    files["obj_units"] = "mm";
    files["texture_dpi"] = tex->texture_dpi;
    files["texture_width_px"] = tex->texture_width_px;
    files["texture_height_px"] = tex->texture_height_px;
    // The garment wearing its print, as the sewn previews see it.
    // An order's copies stand side by side in `worn`: each size is shown on its own body.
    auto print_previews =
        ps.order ? write_order_print_previews(ps, worn, kPrintPreviewDpi)
                 : write_garment_print_previews(out, "garment-print-", worn, ps.body ? &ps.body->mesh() : nullptr,
                                                *ps.renderer, kPrintPreviewDpi);
    if (!print_previews) return fail(print_previews.error());
    files["print_previews"] = *print_previews;
  }

  // Cut contours exactly where the pieces were printed on the roll.
  auto cut = geometry::make_cut_job(ps.pattern, ps.finishing, ps.roll);
  if (!cut) return fail(ErrorCode::kPipeline, "cut files: " + cut.error().message);
  cut->roll_axis = ps.job.finishing.cutter_roll_axis == "y" ? geometry::CutterRollAxis::kY : geometry::CutterRollAxis::kX;
  if (auto st = write_file_atomic(out / "cut.dxf", geometry::dxf_aama_text(*cut)); !st) return st;
  if (auto st = write_file_atomic(out / "cut.svg", geometry::svg_text(*cut)); !st) return st;
  ps.report["files"]["cut"] = {"cut.dxf", "cut.svg"};

  // Warnings a person should read: import notes, pieces no stitch joins, a mirrored print.
  auto& warnings = ps.report["warnings"];
  if (!warnings.is_array()) warnings = nlohmann::json::array();
  for (const std::string& w : ps.pattern.warnings) warnings.push_back("pattern: " + w);
  const nlohmann::json& report = ps.report;  // const: looking up a section must not add it
  const nlohmann::json* checks = nullptr;
  if (report.contains("garment") && report["garment"].contains("checks")) checks = &report["garment"]["checks"];
  // A piece the garment checks list as printed flat gets that one warning (below), not two.
  std::vector<std::string> flat_pieces;
  if (checks && checks->is_object() && checks->contains("unsewn_pieces") && (*checks)["unsewn_pieces"].is_array())
    for (const nlohmann::json& name : (*checks)["unsewn_pieces"])
      if (name.is_string()) flat_pieces.push_back(name.get<std::string>());
  const std::set<std::string> flat_warned(flat_pieces.begin(), flat_pieces.end());
  if (!ps.pattern.stitches.empty()) {
    std::vector<bool> sewn(ps.pattern.pieces.size(), false);
    for (const geometry::Stitch& s : ps.pattern.stitches)
      for (int p : {s.a.piece, s.b.piece})
        if (p >= 0 && static_cast<size_t>(p) < sewn.size()) sewn[static_cast<size_t>(p)] = true;
    for (size_t i = 0; i < sewn.size(); ++i)
      if (!sewn[i] && !flat_warned.count(ps.pattern.pieces[i].name))
        warnings.push_back("piece '" + ps.pattern.pieces[i].name + "' is joined to no other piece by a stitch");
  }
  size_t suggested = 0;
  for (const nlohmann::json& src : ps.stitch_sources) suggested += src.value("source", "") == "suggested";
  if (suggested > 0)
    warnings.push_back(std::to_string(suggested) + " stitch(es) were suggested by `pattern suggest`, not given by the "
                       "pattern or the job: check them before sewing");
  if (ps.garment && !ps.garment_is_3d)
    warnings.push_back("garment: the pieces are laid flat, not sewn on a body: print continuity is matched along the "
                       "stitches in 2D only");
  for (const std::string& name : flat_pieces)
    warnings.push_back("garment: piece '" + name +
                       "' is joined to no other piece: printed flat, not part of the 3D garment");
  // The draped garment only gives previews (unless the job takes its correspondence): a drape
  // that folded through itself does not fail the job, but its pictures are not to be trusted.
  if (report.contains("garment") && report["garment"].contains("drape")) {
    const nlohmann::json& crossed = report["garment"]["drape"]["self_intersections"];
    if (crossed.is_number_integer() && crossed.get<std::int64_t>() > 0)
      warnings.push_back("garment: the draped garment has " + std::to_string(crossed.get<std::int64_t>()) +
                         " self-intersecting triangle pairs: its previews (garment-draped-*.png) show cloth "
                         "through cloth");
  }
  if (ps.job.print.transfer == "sublimation")
    warnings.push_back("print.transfer is sublimation: the printer lays the mirror image for transfer paper");

  if (!ps.pattern.stitches.empty()) {
    auto c = geometry::measure_continuity(ps.pattern, *ps.garment, ps.finishing, *ps.renderer, kContinuityDpi);
    if (!c) return fail(ErrorCode::kPipeline, "continuity: " + c.error().message);
    ps.report["seams"] = stats_json(c->seams);
    ps.report["seams"]["dpi"] = kContinuityDpi;
    ps.report["seams"]["count"] = c->seam_list.size();
    ps.report["allowance"] = stats_json(c->allowance);
    ps.report["allowance"]["count"] = c->allowance_list.size();

    // The same sample pairs on what was printed (docs/colour.md): only a print can show a piece
    // placed, turned or fed off its planned place.
    auto printed = measure_printed_seams(ps, kContinuityDpi);
    if (!printed) return fail(printed.error());
    if (printed->report) {
      const geometry::ContinuityReport& pr = *printed->report;
      ps.report["seams_printed"] = stats_json(pr.seams);
      ps.report["seams_printed"]["count"] = pr.seam_list.size();
      ps.report["allowance_printed"] = stats_json(pr.allowance);
      ps.report["allowance_printed"]["count"] = pr.allowance_list.size();
      for (const char* key : {"seams_printed", "allowance_printed"}) {
        ps.report[key]["dpi"] = kContinuityDpi;
        ps.report[key]["aperture_mm"] = printed_aperture_mm(ps.job.print.dpi);
        ps.report[key]["fabric"] = printed->fabric_lab.filename().string();
      }
      nlohmann::json worst = nlohmann::json::array();
      for (const geometry::SeamContinuity& s : pr.seam_list)
        worst.push_back({{"piece_a", s.piece_a},
                         {"edge_a", s.edge_a},
                         {"piece_b", s.piece_b},
                         {"edge_b", s.edge_b},
                         {"samples", s.de00.samples},
                         {"de00_mean", s.de00.mean},
                         {"de00_p95", s.de00.p95}});
      ps.report["seams_printed"]["list"] = worst;
      // The largest few sample pairs, piece-local mm: where on the garment to look.
      for (const auto& [key, samples] : {std::pair{"seams_printed", &pr.worst_seam_samples},
                                         std::pair{"allowance_printed", &pr.worst_allowance_samples}}) {
        nlohmann::json w = nlohmann::json::array();
        for (const geometry::SamplePair& sp : *samples)
          w.push_back({{"de00", sp.de00},
                       {"piece_a", sp.piece_a},
                       {"at_a_mm", {sp.at_a_mm.x, sp.at_a_mm.y}},
                       {"piece_b", sp.piece_b},
                       {"at_b_mm", {sp.at_b_mm.x, sp.at_b_mm.y}}});
        ps.report[key]["worst_samples"] = w;
      }
    } else {
      for (const char* key : {"seams_printed", "allowance_printed"}) {
        ps.report[key] = stats_json({});
        ps.report[key]["count"] = 0;
        ps.report[key]["reason"] = printed->reason;
      }
    }
  }
  // What of the design the printer cannot reproduce, and the soft proof that shows it.
  return report_gamut(ps);
}

}  // namespace tp::host::internal
