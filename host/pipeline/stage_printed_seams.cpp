// host/pipeline/stage_printed_seams.cpp: seams and allowances measured on the printed fabric: the
// fabric's CIELAB image, descreened by an aperture average, read where the marker put each piece.
#include <algorithm>
#include <cmath>
#include <fstream>

#include "device/colour/colorimetry.h"
#include "host/pipeline/internal/printed_fabric_wait.h"
#include "host/pipeline/internal/printed_seams.h"
#include "host/session/sim_reexec.h"
#include "rip/colour/lab_image.h"

namespace tp::host::internal {

namespace fs = std::filesystem;

namespace {

// The fabric image averaged in XYZ over a square aperture centred on a roll point (mm).
std::optional<geometry::Lab> aperture_lab(const rip::Image3f& img, geometry::Vec2 roll_mm, double aperture_mm) {
  const double half_px = 0.5 * aperture_mm * img.px_per_mm;
  const double cx = roll_mm.x * img.px_per_mm, cy = roll_mm.y * img.px_per_mm;
  const double x0 = cx - half_px, x1 = cx + half_px, y0 = cy - half_px, y1 = cy + half_px;
  if (x0 < 0 || y0 < 0 || x1 > img.width_px || y1 > img.height_px) return std::nullopt;
  device::Xyz sum;
  double weight = 0;
  for (int y = static_cast<int>(std::floor(y0)); y < static_cast<int>(std::ceil(y1)); ++y) {
    const double wy = std::min<double>(y + 1, y1) - std::max<double>(y, y0);
    for (int x = static_cast<int>(std::floor(x0)); x < static_cast<int>(std::ceil(x1)); ++x) {
      const double w = wy * (std::min<double>(x + 1, x1) - std::max<double>(x, x0));
      if (w <= 0) continue;
      const float* p = img.at(x, y);
      const device::Xyz c = device::lab_to_xyz({p[0], p[1], p[2]});
      sum.x += w * c.x;
      sum.y += w * c.y;
      sum.z += w * c.z;
      weight += w;
    }
  }
  if (!(weight > 0)) return std::nullopt;
  const device::Lab lab = device::xyz_to_lab({sum.x / weight, sum.y / weight, sum.z / weight});
  return geometry::Lab{lab.l, lab.a, lab.b};
}

// Even-odd point in polygon.
bool inside(const geometry::Polygon& poly, geometry::Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const geometry::Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

double distance_to(const geometry::Polygon& poly, geometry::Vec2 p) {
  double best = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const geometry::Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const geometry::Vec2 d = b - a;
    const double len2 = geometry::dot(d, d);
    const double t = len2 > 0 ? std::clamp(geometry::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, geometry::norm(p - (a + d * t)));
  }
  return best;
}

}  // namespace

double printed_aperture_mm(int printer_dpi) {
  return printer_dpi > 0 ? std::max(kPrintedApertureMin_mm, kPrintedApertureDrops * 25.4 / printer_dpi)
                         : kPrintedApertureMin_mm;
}

Result<geometry::Marker> printed_roll(const PipelineState& ps) {
  geometry::Marker roll = ps.roll;
  const auto& m = ps.options.misplace_for_test;
  if (!m) return roll;
  int piece = -1;
  for (std::size_t i = 0; i < ps.pattern.pieces.size(); ++i)
    if (ps.pattern.pieces[i].name == m->piece) piece = static_cast<int>(i);
  if (piece < 0) return fail(ErrorCode::kInvalidArgument, "misplace (test hook): no piece named '" + m->piece + "'");
  const geometry::Polygon& cut = ps.renderer->cut_outline_mm(piece);
  bool placed = false;
  for (geometry::PiecePlacement& pl : roll.placements) {
    if (pl.piece != piece) continue;
    // Turn about the centre of the cut outline's bounding box on the roll, then move.
    geometry::Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    const geometry::Affine2 t = pl.piece_to_roll();
    for (geometry::Vec2 v : cut) {
      const geometry::Vec2 r = t.apply(v);
      lo = {std::min(lo.x, r.x), std::min(lo.y, r.y)};
      hi = {std::max(hi.x, r.x), std::max(hi.y, r.y)};
    }
    const geometry::Vec2 c = (lo + hi) * 0.5;
    const geometry::Affine2 turn = geometry::Affine2::rotation_deg(m->rotation_deg);
    pl.offset_mm = c + geometry::Vec2{m->dx_mm, m->dy_mm} + turn.apply_linear(pl.offset_mm - c);
    pl.rotation_deg += m->rotation_deg;
    placed = true;
  }
  if (!placed)
    return fail(ErrorCode::kInvalidArgument, "misplace (test hook): piece '" + m->piece + "' is not on the roll");
  return roll;
}

Result<PrintedSeams> measure_printed_seams_on(const PipelineState& ps, double dpi, const fs::path& fabric_lab) {
  PrintedSeams out;
  out.fabric_lab = fabric_lab;
  auto img = rip::read_image3f(fabric_lab);
  if (!img) return fail(ErrorCode::kPipeline, "printed seams: " + img.error().message);
  if (!(img->px_per_mm > 0))
    return fail(ErrorCode::kPipeline, "printed seams: " + fabric_lab.string() + ": no resolution");
  // Each piece goes to the roll by its (first) placement in the plan, not where it was printed.
  std::vector<std::optional<geometry::Affine2>> to_roll(ps.pattern.pieces.size());
  for (const geometry::PiecePlacement& pl : ps.roll.placements)
    if (pl.piece >= 0 && static_cast<std::size_t>(pl.piece) < to_roll.size() &&
        !to_roll[static_cast<std::size_t>(pl.piece)])
      to_roll[static_cast<std::size_t>(pl.piece)] = pl.piece_to_roll();
  const rip::Image3f& image = *img;
  const double aperture = printed_aperture_mm(ps.job.print.dpi);
  // The aperture is wider than a contone pixel: it must not reach past the cut line (unprinted
  // fabric, another piece) nor around a corner of the seam line, where the allowance mitres between
  // two sources and the two sides of a seam cover different prints.
  std::vector<std::vector<geometry::Vec2>> corners(ps.pattern.pieces.size());
  for (std::size_t p = 0; p < corners.size(); ++p)
    for (const geometry::Edge& e : ps.pattern.pieces[p].edges)
      if (!e.points_mm.empty()) corners[p].insert(corners[p].end(), {e.points_mm.front(), e.points_mm.back()});
  auto clear_of_edges = [&](int piece, geometry::Vec2 at) {
    for (geometry::Vec2 c : corners[static_cast<std::size_t>(piece)])
      if (geometry::norm(at - c) < kPrintedCornerClearance * aperture) return false;
    const geometry::Polygon& cut = ps.renderer->cut_outline_mm(piece);
    return inside(cut, at) && distance_to(cut, at) >= 0.75 * aperture;
  };
  geometry::ContinuityOptions options;
  options.sample = [&](int piece, geometry::Vec2 at_mm) -> std::optional<geometry::Lab> {
    if (piece < 0 || static_cast<std::size_t>(piece) >= to_roll.size() || !to_roll[static_cast<std::size_t>(piece)])
      return std::nullopt;
    if (!clear_of_edges(piece, at_mm)) return std::nullopt;
    return aperture_lab(image, to_roll[static_cast<std::size_t>(piece)]->apply(at_mm), aperture);
  };
  auto c = geometry::measure_continuity(ps.pattern, *ps.garment, ps.finishing, *ps.renderer, dpi, options);
  if (!c) return fail(ErrorCode::kPipeline, "printed seams: " + c.error().message);
  out.report = std::move(*c);
  return out;
}

Result<PrintedSeams> measure_printed_seams(const PipelineState& ps, double dpi, double wait_s) {
  PrintedSeams none;
  if (ps.job.print.transfer == "sublimation") {
    none.reason = "the print is a mirror image for transfer paper: it is measured after the transfer, not here";
    return none;
  }
  const auto sim_dir = printsim_out_dir();
  if (effective_printer(ps.job.print.printer, ps.options.printer_override) != PrinterChoice::kSim || !sim_dir) {
    none.reason = "no printed fabric image: the printer is not printsim (measure a scan with printctl proof-check)";
    return none;
  }
  // printsim writes the fabric images, then printer.json, once the job has ended.
  PrintedFabricWait wait{*sim_dir, ps.options.job_id, ps.print_began, wait_s};
  auto fabric = wait_for_printed_fabric(wait, ps.cancel);
  if (!fabric) return fail(fabric.error().with_context("printed seams"));
  if (!fabric->fabric_lab) {
    none.reason = fabric->reason;
    return none;
  }
  return measure_printed_seams_on(ps, dpi, *fabric->fabric_lab);
}

}  // namespace tp::host::internal
