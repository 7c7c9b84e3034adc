// geometry/cutfile/cut_job.cpp: per-placement cut contours from the pattern and finishing.
#include "geometry/cutfile/cut_job.h"

#include <algorithm>
#include <map>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/cut_outline.h"
#include "geometry/allowance/marks.h"
#include "geometry/allowance/notches.h"

namespace tp::geometry {

namespace {

// Cuts V and U notches into the outline where they open on it (slits and T notches are cut by
// the knife along layer 4 and leave the outline as it is).
Polygon notched_outline(const Polygon& cut, const std::vector<NotchCut>& notches) {
  Polygon out = cut;
  for (const NotchCut& n : notches) {
    if (n.type != NotchType::kV && n.type != NotchType::kU) continue;
    if (n.strokes.empty() || n.strokes.front().size() < 3) continue;
    const auto& shape = n.strokes.front();
    // The outline segment the notch opens on: nearest to its opening point.
    size_t best = 0;
    double best_d = 1e300;
    for (size_t i = 0; i < out.size(); ++i) {
      const Vec2 a = out[i], b = out[(i + 1) % out.size()];
      const Vec2 d = b - a;
      const double len2 = dot(d, d);
      const double t = len2 > 0 ? std::clamp(dot(n.cut_point_mm - a, d) / len2, 0.0, 1.0) : 0.0;
      const double dist = norm(n.cut_point_mm - (a + d * t));
      if (dist < best_d) best_d = dist, best = i;
    }
    const Vec2 a = out[best], b = out[(best + 1) % out.size()];
    // Only on a segment long enough to hold the notch's mouth, else leave it to layer 4.
    if (best_d > 0.05 || norm(b - a) < norm(shape.back() - shape.front()) + 0.2) continue;
    // The shape runs along the cut line in the outline's direction or against it.
    std::vector<Vec2> ins(shape.begin(), shape.end());
    if (dot(shape.back() - shape.front(), b - a) < 0) std::reverse(ins.begin(), ins.end());
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(best) + 1, ins.begin(), ins.end());
  }
  return out;
}

}  // namespace

Affine2 roll_to_cutter(const CutJob& job) {
  // Both maps turn the printed face's y-down view into a y-up drawing without mirroring it.
  if (job.roll_axis == CutterRollAxis::kX) return Affine2{0, 1, 0, 1, 0, 0};
  return Affine2{1, 0, 0, 0, -1, job.marker_length_mm};
}

std::vector<Vec2> transformed(const std::vector<Vec2>& pts, const Affine2& m) {
  std::vector<Vec2> out;
  out.reserve(pts.size());
  for (Vec2 p : pts) out.push_back(m.apply(p));
  return out;
}

Result<CutJob> make_cut_job(const Pattern& pattern, const Finishing& finishing, const Marker& marker) {
  if (auto st = validate_finishing(pattern, finishing); !st) return std::unexpected(st.error());
  CutJob job;
  job.job_name = finishing.job_name;
  job.pattern_name = pattern.name;
  job.size = pattern.size;
  job.fabric_width_mm = marker.width_mm;
  job.marker_length_mm = marker.length_mm;
  std::map<int, int> copies;
  for (size_t i = 0; i < marker.placements.size(); ++i) {
    const PiecePlacement& pl = marker.placements[i];
    if (pl.piece < 0 || static_cast<size_t>(pl.piece) >= pattern.pieces.size())
      return fail(ErrorCode::kInvalidArgument,
                  "marker.placements[" + std::to_string(i) + "].piece: no piece " + std::to_string(pl.piece));
    const Piece& pc = pattern.pieces[static_cast<size_t>(pl.piece)];
    auto allowance = resolve_allowance(pattern, pl.piece, finishing);
    if (!allowance) return std::unexpected(allowance.error());
    auto cut = cut_outline(pc, *allowance, finishing.mitre_limit);
    if (!cut) return std::unexpected(cut.error().with_context("marker.placements[" + std::to_string(i) + "]"));
    PieceCut c;
    const int copy = ++copies[pl.piece];
    c.name = copy == 1 ? pc.name : pc.name + "#" + std::to_string(copy);
    c.piece = pl.piece;
    c.piece_to_roll = pl.piece_to_roll();
    c.mirrored = pl.mirrored;
    c.cut_line = *cut;
    c.sew_line = outline(pc);
    const auto notches = piece_notches(pattern, pl.piece, *allowance, *cut, finishing);
    for (const NotchCut& n : notches) {
      c.notch_lines.push_back({n.cut_point_mm, n.cut_point_mm + n.inward * n.depth_mm});
      c.notch_types.push_back(n.type);
      for (const auto& s : n.strokes) c.notch_shapes.push_back(s);
    }
    c.cut_line_notched = notched_outline(*cut, notches);
    if (pc.grain) c.grain.push_back({pc.grain->from_mm, pc.grain->to_mm});
    c.drill_holes = pc.drill_holes;
    for (const InternalLine& l : pc.internal_lines) c.internal_lines.push_back(l.points_mm);
    if (finishing.marks == MarkMode::kMarkerLayer) {
      const PieceMarks m = piece_marks(pc, *allowance, pattern.size, finishing);
      c.mark_strokes = m.label;
      c.mark_strokes.insert(c.mark_strokes.end(), m.grain_arrow.begin(), m.grain_arrow.end());
    }
    c.annotation = {"Piece Name: " + c.name, "Quantity: 1"};
    if (!pattern.size.empty()) c.annotation.push_back("Size: " + pattern.size);
    if (!pc.material.empty()) c.annotation.push_back("Material: " + pc.material);
    if (!pattern.name.empty()) c.annotation.push_back("Style Name: " + pattern.name);
    if (!finishing.job_name.empty()) c.annotation.push_back("Job: " + finishing.job_name);
    c.annotation.push_back("Units: METRIC");
    job.pieces.push_back(std::move(c));
  }
  return job;
}

}  // namespace tp::geometry
