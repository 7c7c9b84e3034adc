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
#include "geometry/common/thread_pool.h"
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

// Two piece-local points whose colours should match, and what comparing them gave.
struct SamplePairJob {
  int pa = -1;
  Vec2 a;
  int pb = -1;
  Vec2 b;
};
struct SampleResult {
  std::optional<double> de00;  ///< nullopt: skipped (by the sampler, or by the allowance's filters)
  Rgba8 ca{}, cb{};
};

// Renders both pixels and returns their difference. Without a sampler of its own the colours
// are the renderer's; a sampler may skip a pair (nullopt). Safe to call from several threads.
SampleResult compare(const PieceRenderer& r, const ContinuityOptions& o, const SamplePairJob& j, double mm_per_px) {
  SampleResult out;
  if (o.sample) {
    const auto la = o.sample(j.pa, j.a);
    if (!la) return out;
    const auto lb = o.sample(j.pb, j.b);
    if (!lb) return out;
    out.de00 = ciede2000(*la, *lb);
  } else {
    out.ca = pixel_at(r, j.pa, j.a, mm_per_px);
    out.cb = pixel_at(r, j.pb, j.b, mm_per_px);
    out.de00 = ciede2000(srgb_over_white_to_lab(out.ca), srgb_over_white_to_lab(out.cb));
  }
  return out;
}

// Keeps the pair if it is among the worst; called in sample order, so ties keep one order.
void keep_worst(const Pattern& pattern, const SamplePairJob& j, const SampleResult& res,
                std::vector<SamplePair>& worst) {
  const double de = *res.de00;
  if (worst.size() < kWorstKept || de > worst.back().de00) {
    worst.push_back({de, pattern.pieces[static_cast<size_t>(j.pa)].name, pattern.pieces[static_cast<size_t>(j.pb)].name,
                     j.a, j.b, res.ca, res.cb});
    std::sort(worst.begin(), worst.end(), [](const SamplePair& x, const SamplePair& y) { return x.de00 > y.de00; });
    if (worst.size() > kWorstKept) worst.pop_back();
  }
}

// Samples handed to a thread at a time.
constexpr int kSamplesPerTask = 256;

// Runs fn(i) for i in [0, count) on the pool, in tasks of kSamplesPerTask.
template <class Fn>
void for_samples(ThreadPool& pool, size_t count, Fn&& fn) {
  const int tasks = static_cast<int>((count + kSamplesPerTask - 1) / kSamplesPerTask);
  pool.parallel_for(tasks, [&](int task, int) {
    const size_t end = std::min(count, static_cast<size_t>(task + 1) * kSamplesPerTask);
    for (size_t i = static_cast<size_t>(task) * kSamplesPerTask; i < end; ++i) fn(i);
  });
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

  ThreadPool pool(options.threads);

  // Seams: pairs of pixels centred on the same 3D point, one in each piece. Listed in order,
  // compared on the pool, gathered in order: the same figures for any thread count.
  using SeamKey = std::tuple<int, int, int, int>;
  std::vector<SamplePairJob> seam_jobs;
  std::vector<SeamKey> seam_keys;
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
      for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        const double tb = seg.partner_reversed ? 1 - t : t;
        seam_jobs.push_back({p, a0 + (a1 - a0) * t, seg.partner_piece, b0 + (b1 - b0) * tb});
        seam_keys.emplace_back(p, seg.edge, seg.partner_piece, ps.edge);
      }
    }
  }
  std::vector<SampleResult> seam_results(seam_jobs.size());
  for_samples(pool, seam_jobs.size(),
              [&](size_t i) { seam_results[i] = compare(renderer, options, seam_jobs[i], mm_per_px); });
  std::map<SeamKey, std::vector<double>> seams;
  std::vector<double> all_seams;
  for (size_t i = 0; i < seam_jobs.size(); ++i) {
    auto& bucket = seams[seam_keys[i]];
    if (!seam_results[i].de00) continue;
    keep_worst(pattern, seam_jobs[i], seam_results[i], report.worst_seam_samples);
    bucket.push_back(*seam_results[i].de00);
    all_seams.push_back(*seam_results[i].de00);
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
      // Every (segment, position, depth) in order; each is checked and compared on the pool.
      std::vector<SeamCoordinates> candidates;
      for (size_t k = 0; k < chart.segments.size(); ++k) {
        const auto& seg = chart.segments[k];
        const double w = widths->width_mm[static_cast<size_t>(seg.edge)];
        if (w <= 0) continue;
        const double step = std::max(spacing, kAllowanceSpacing_mm);
        const int n = std::max(1, static_cast<int>(std::ceil(norm(V[static_cast<size_t>(seg.b)] - V[static_cast<size_t>(seg.a)]) / step)));
        for (int i = 0; i < n; ++i)
          for (double f : options.depth_fractions) candidates.push_back({static_cast<int>(k), (i + 0.5) / n, f * w});
      }
      struct Checked {
        SamplePairJob job;  // job.pb: the piece the allowance copies
        int category = 0;
        SampleResult result;  // de00 nullopt: skipped
      };
      std::vector<Checked> checked(candidates.size());
      for_samples(pool, candidates.size(), [&](size_t c) {
        const SeamCoordinates& sc = candidates[c];
        const Vec2 x = source.seam_point(p, sc);
        const SeamCoordinates back = source.seam_coordinates(p, x);
        if (back.segment != sc.segment || norm(source.seam_point(p, back) - x) > kRoundTrip_mm ||
            std::abs(back.d_mm - sc.d_mm) > kRoundTrip_mm)
          return;
        if (!internal::inside_polygon(cut, x) || distance_to_outline(cut, x) < kEdgeMargin_px * mm_per_px) return;
        if (near_mark(x)) return;
        const auto s = source.source(p, sc);
        if (s.location.triangle < 0 || norm(surface.chart_position(s.piece, s.location) - s.position_mm) > kClamp_mm)
          return;
        // A pixel astride a line where the print source changes (the mitre at a corner between
        // a seam and a hem, or between two partners) shows either side: not a copy to measure.
        for (Vec2 o : {Vec2{0.5, 0}, Vec2{-0.5, 0}, Vec2{0, 0.5}, Vec2{0, -0.5}}) {
          const auto n = source.source(p, x + o * mm_per_px);
          if (n.piece != s.piece || n.category != s.category) return;
        }
        Checked& out = checked[c];
        out.job = {p, x, s.piece, s.position_mm};
        out.category = s.category;
        out.result = compare(renderer, options, out.job, mm_per_px);
      });
      std::map<std::tuple<int, int, int>, std::vector<double>> groups;
      for (size_t c = 0; c < candidates.size(); ++c) {
        const Checked& ch = checked[c];
        if (!ch.result.de00) continue;
        keep_worst(pattern, ch.job, ch.result, report.worst_allowance_samples);
        const int edge = chart.segments[static_cast<size_t>(candidates[c].segment)].edge;
        groups[{edge, ch.job.pb, ch.category}].push_back(*ch.result.de00);
        all_allowance.push_back(*ch.result.de00);
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
