// geometry/continuity/continuity.cpp: seam and allowance sample pairs, rendered and compared.
#include "geometry/continuity/continuity.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <tuple>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/marks.h"
#include "geometry/continuity/ciede2000.h"
#include "geometry/design/internal/allowance_source.h"
#include "geometry/design/internal/band_mesh.h"
#include "geometry/design/internal/garment_surface.h"

namespace tp::geometry {
namespace {

using internal::AllowanceSource;
using internal::GarmentSurface;
using internal::SeamCoordinates;

// A seam coordinate read back from a sample point must land within this of where it was made.
constexpr double kRoundTrip_mm = 0.05;
// A source point clamped farther than this into a narrow partner is not a faithful copy.
constexpr double kClamp_mm = 0.05;
// Allowance samples this close to the cut line are skipped (their pixel straddles the edge).
constexpr double kEdgeMargin_px = 1.0;
// Allowance samples (three depths per position) are spaced at least this far along the seam.
constexpr double kAllowanceSpacing_mm = 0.4;

Rgba8 pixel_at(const PieceRenderer& r, int piece, Vec2 p, double mm_per_px) {
  Rgba8 px{};
  r.render(piece, Affine2{mm_per_px, 0, p.x - 0.5 * mm_per_px, 0, -mm_per_px, p.y + 0.5 * mm_per_px}, 1, 1, &px, 1);
  return px;
}

// How many of the worst sample pairs the report keeps.
constexpr size_t kWorstKept = 8;

// Renders both pixels, returns their difference and keeps the pair if it is among the worst.
// Without a sampler of its own the colours are the renderer's; a sampler may skip a pair (nullopt).
std::optional<double> difference(const Pattern& pattern, const PieceRenderer& r, const ContinuityOptions& o, int pa,
                                 Vec2 a, int pb, Vec2 b, double mm_per_px, std::vector<SamplePair>& worst) {
  Rgba8 ca{}, cb{};
  double de = 0;
  if (o.sample) {
    const auto la = o.sample(pa, a);
    if (!la) return std::nullopt;
    const auto lb = o.sample(pb, b);
    if (!lb) return std::nullopt;
    de = ciede2000(*la, *lb);
  } else {
    ca = pixel_at(r, pa, a, mm_per_px);
    cb = pixel_at(r, pb, b, mm_per_px);
    de = ciede2000(srgb_over_white_to_lab(ca), srgb_over_white_to_lab(cb));
  }
  if (worst.size() < kWorstKept || de > worst.back().de00) {
    worst.push_back({de, pattern.pieces[static_cast<size_t>(pa)].name, pattern.pieces[static_cast<size_t>(pb)].name, a, b, ca, cb});
    std::sort(worst.begin(), worst.end(), [](const SamplePair& x, const SamplePair& y) { return x.de00 > y.de00; });
    if (worst.size() > kWorstKept) worst.pop_back();
  }
  return de;
}

double distance_to_outline(const Polygon& poly, Vec2 p) {
  double best = 1e300;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const Vec2 d = b - a;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, norm(p - (a + d * t)));
  }
  return best;
}

const std::string& edge_name(const Pattern& pattern, int piece, int edge) {
  static const std::string none = "?";
  const Piece& pc = pattern.pieces[static_cast<size_t>(piece)];
  return edge >= 0 && static_cast<size_t>(edge) < pc.edges.size() ? pc.edges[static_cast<size_t>(edge)].name : none;
}

}  // namespace

DeltaEStats summarise(std::vector<double>& v) {
  DeltaEStats s;
  s.samples = v.size();
  if (v.empty()) return s;
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(v.size()))) - 1;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(rank), v.end());
  s.p95 = v[rank];
  s.max = *std::max_element(v.begin(), v.end());
  return s;
}

Result<ContinuityReport> measure_continuity(const Pattern& pattern, const Garment& garment, const Finishing& finishing,
                                           const PieceRenderer& renderer, double dpi, const ContinuityOptions& options) {
  if (!(dpi > 0) || !std::isfinite(dpi)) return fail(ErrorCode::kInvalidArgument, "continuity: dpi must be > 0");
  auto built = GarmentSurface::build(pattern, garment);
  if (!built) return std::unexpected(built.error().with_context("continuity"));
  const GarmentSurface& surface = **built;
  if (renderer.piece_count() != surface.piece_count())
    return fail(ErrorCode::kInvalidArgument, "continuity: the renderer has " + std::to_string(renderer.piece_count()) +
                                                 " pieces, the garment " + std::to_string(surface.piece_count()));
  const AllowanceSource source(surface);
  const double mm_per_px = 25.4 / dpi;
  const double spacing = options.spacing_mm > 0 ? options.spacing_mm : std::max(mm_per_px, 0.2);
  ContinuityReport report;
  report.dpi = dpi;

  // Seams: pairs of pixels centred on the same 3D point, one in each piece.
  std::map<std::tuple<int, int, int, int>, std::vector<double>> seams;
  std::vector<double> all_seams;
  for (int p = 0; p < surface.piece_count(); ++p) {
    const auto& chart = surface.chart(p);
    const auto& V = chart.piece->mesh.vertices_mm;
    for (size_t k = 0; k < chart.segments.size(); ++k) {
      const auto& seg = chart.segments[k];
      if (seg.partner_piece < 0) continue;
      if (seg.partner_piece < p || (seg.partner_piece == p && seg.partner_segment < static_cast<int>(k))) continue;
      const auto& other = surface.chart(seg.partner_piece);
      const auto& ps = other.segments[static_cast<size_t>(seg.partner_segment)];
      const auto& W = other.piece->mesh.vertices_mm;
      const Vec2 a0 = V[static_cast<size_t>(seg.a)], a1 = V[static_cast<size_t>(seg.b)];
      const Vec2 b0 = W[static_cast<size_t>(ps.a)], b1 = W[static_cast<size_t>(ps.b)];
      const int n = std::max(1, static_cast<int>(std::ceil(norm(a1 - a0) / spacing)));
      auto& bucket = seams[{p, seg.edge, seg.partner_piece, ps.edge}];
      for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        const double tb = seg.partner_reversed ? 1 - t : t;
        const auto de = difference(pattern, renderer, options, p, a0 + (a1 - a0) * t, seg.partner_piece,
                                   b0 + (b1 - b0) * tb, mm_per_px, report.worst_seam_samples);
        if (!de) continue;
        bucket.push_back(*de);
        all_seams.push_back(*de);
      }
    }
  }
  for (auto& [key, values] : seams) {
    if (values.empty()) continue;
    const auto [p, e, q, f] = key;
    report.seam_list.push_back({pattern.pieces[static_cast<size_t>(p)].name, edge_name(pattern, p, e),
                                pattern.pieces[static_cast<size_t>(q)].name, edge_name(pattern, q, f), summarise(values)});
  }
  report.seams = summarise(all_seams);

  // Allowance: points at fractions of the width outside the seam line against their sources.
  std::vector<double> all_allowance;
  if (finishing.textured_allowance) {
    for (int p = 0; p < surface.piece_count(); ++p) {
      auto widths = resolve_allowance(pattern, p, finishing);
      if (!widths) return std::unexpected(widths.error().with_context("continuity"));
      const Polygon& cut = renderer.cut_outline_mm(p);
      // Printed labels and grain arrows sit in the allowance on purpose: not part of the copy.
      std::vector<std::array<Vec2, 2>> marks;
      double mark_reach = 0;
      if (finishing.marks == MarkMode::kPrinted) {
        const PieceMarks pm = piece_marks(pattern.pieces[static_cast<size_t>(p)], *widths, pattern.size, finishing);
        mark_reach = 0.5 * pm.stroke_width_mm + 1.5 * mm_per_px;
        for (const auto* set : {&pm.label, &pm.grain_arrow})
          for (const auto& l : *set)
            for (size_t i = 0; i + 1 < l.size(); ++i) marks.push_back({l[i], l[i + 1]});
      }
      auto near_mark = [&](Vec2 x) {
        for (const auto& m : marks) {
          const Vec2 d = m[1] - m[0];
          const double len2 = dot(d, d);
          const double t = len2 > 0 ? std::clamp(dot(x - m[0], d) / len2, 0.0, 1.0) : 0.0;
          if (norm(x - (m[0] + d * t)) < mark_reach) return true;
        }
        return false;
      };
      const auto& chart = surface.chart(p);
      const auto& V = chart.piece->mesh.vertices_mm;
      std::map<std::tuple<int, int, int>, std::vector<double>> groups;
      for (size_t k = 0; k < chart.segments.size(); ++k) {
        const auto& seg = chart.segments[k];
        const double w = widths->width_mm[static_cast<size_t>(seg.edge)];
        if (w <= 0) continue;
        const double step = std::max(spacing, kAllowanceSpacing_mm);
        const int n = std::max(1, static_cast<int>(std::ceil(norm(V[static_cast<size_t>(seg.b)] - V[static_cast<size_t>(seg.a)]) / step)));
        for (int i = 0; i < n; ++i) {
          for (double f : options.depth_fractions) {
            const SeamCoordinates sc{static_cast<int>(k), (i + 0.5) / n, f * w};
            const Vec2 x = source.seam_point(p, sc);
            const SeamCoordinates back = source.seam_coordinates(p, x);
            if (back.segment != sc.segment || norm(source.seam_point(p, back) - x) > kRoundTrip_mm ||
                std::abs(back.d_mm - sc.d_mm) > kRoundTrip_mm)
              continue;
            if (!internal::inside_polygon(cut, x) || distance_to_outline(cut, x) < kEdgeMargin_px * mm_per_px) continue;
            if (near_mark(x)) continue;
            const auto s = source.source(p, sc);
            if (s.location.triangle < 0 || norm(surface.chart_position(s.piece, s.location) - s.position_mm) > kClamp_mm) continue;
            // A pixel astride a line where the print source changes (the mitre at a corner between
            // a seam and a hem, or between two partners) shows either side: not a copy to measure.
            bool astride = false;
            for (Vec2 o : {Vec2{0.5, 0}, Vec2{-0.5, 0}, Vec2{0, 0.5}, Vec2{0, -0.5}}) {
              const auto n = source.source(p, x + o * mm_per_px);
              astride |= n.piece != s.piece || n.category != s.category;
            }
            if (astride) continue;
            const auto de = difference(pattern, renderer, options, p, x, s.piece, s.position_mm, mm_per_px,
                                       report.worst_allowance_samples);
            if (!de) continue;
            groups[{seg.edge, s.piece, s.category}].push_back(*de);
            all_allowance.push_back(*de);
          }
        }
      }
      for (auto& [key, values] : groups) {
        const auto [e, q, cat] = key;
        report.allowance_list.push_back({pattern.pieces[static_cast<size_t>(p)].name, edge_name(pattern, p, e),
                                         pattern.pieces[static_cast<size_t>(q)].name, cat, summarise(values)});
      }
    }
  }
  report.allowance = summarise(all_allowance);
  return report;
}

std::string continuity_json(const ContinuityReport& r) {
  auto stats = [](const DeltaEStats& s) {
    return nlohmann::json{{"samples", s.samples}, {"de00_mean", s.mean}, {"de00_p95", s.p95}, {"de00_max", s.max}};
  };
  nlohmann::json seams = stats(r.seams);
  seams["list"] = nlohmann::json::array();
  for (const auto& s : r.seam_list) {
    auto j = stats(s.de00);
    j["piece_a"] = s.piece_a;
    j["edge_a"] = s.edge_a;
    j["piece_b"] = s.piece_b;
    j["edge_b"] = s.edge_b;
    seams["list"].push_back(j);
  }
  nlohmann::json allowance = stats(r.allowance);
  allowance["list"] = nlohmann::json::array();
  for (const auto& a : r.allowance_list) {
    auto j = stats(a.de00);
    j["piece"] = a.piece;
    j["edge"] = a.edge;
    j["source_piece"] = a.source_piece;
    j["category"] = a.category;
    allowance["list"].push_back(j);
  }
  return nlohmann::json{{"dpi", r.dpi}, {"seams", seams}, {"allowance", allowance}}.dump();
}

}  // namespace tp::geometry
