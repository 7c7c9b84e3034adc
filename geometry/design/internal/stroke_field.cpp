// geometry/design/internal/stroke_field.cpp: stroke sampling, snapping and surface reach.
#include "geometry/design/internal/stroke_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "geometry/common/tolerances.h"

namespace tp::geometry::internal {
namespace {

constexpr float kUnreached = std::numeric_limits<float>::infinity();
// Stroke samples are at most this far apart, and never farther than a quarter radius.
constexpr double kMaxSampleSpacing_mm = 2.0;
// Dijkstra along mesh edges overestimates surface distance by up to this factor (metrication).
constexpr double kGraphStretch = 1.3;

}  // namespace

double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + ab * t));
}

double segment_segment_distance(Vec3 p, Vec3 q, Vec3 a, Vec3 b) {
  // Closest points of two segments (clamped parameters), then the four end-point cases as a
  // guard for parallel or degenerate segments.
  const Vec3 d1 = q - p, d2 = b - a, r = p - a;
  const double A = dot(d1, d1), E = dot(d2, d2), F = dot(d2, r);
  double best = std::min({point_segment_distance(p, a, b), point_segment_distance(q, a, b),
                          point_segment_distance(a, p, q), point_segment_distance(b, p, q)});
  if (A <= 0 || E <= 0) return best;
  const double C = dot(d1, r), B = dot(d1, d2);
  const double den = A * E - B * B;
  if (den <= kParallelDeterminant * A * E) return best;
  const double s = std::clamp((B * F - C * E) / den, 0.0, 1.0);
  const double t = std::clamp((B * s + F) / E, 0.0, 1.0);
  return std::min(best, norm((p + d1 * s) - (a + d2 * t)));
}

StrokeField::StrokeField(const BrushStroke& stroke, const GarmentSurface& surface, const ClosestPointIndex& index)
    : surface_(surface), radius_mm_(stroke.radius_mm), hardness_(std::clamp(stroke.hardness, 0.0, 1.0)) {
  const auto& V = surface.garment().vertices_mm;
  // Adjacency of the 3D vertex graph (seams share vertices, so the graph crosses them).
  std::vector<std::vector<std::pair<int, float>>> adj(V.size());
  double max_edge = 0;
  for (const auto& t : surface.triangles_3d()) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<size_t>(k)], b = t[static_cast<size_t>((k + 1) % 3)];
      const double len = norm(V[static_cast<size_t>(a)] - V[static_cast<size_t>(b)]);
      max_edge = std::max(max_edge, len);
      adj[static_cast<size_t>(a)].push_back({b, static_cast<float>(len)});
      adj[static_cast<size_t>(b)].push_back({a, static_cast<float>(len)});
    }
  }
  gate_slack_mm_ = 2 * max_edge;

  // Resample the polyline and snap every sample onto the surface.
  const double spacing = std::min(kMaxSampleSpacing_mm, std::max(radius_mm_ / 4, 0.05));
  std::vector<MeshHit> samples;
  const auto& P = stroke.points_mm;
  for (size_t i = 0; i < P.size(); ++i) {
    const Vec3 a = P[i];
    const Vec3 b = i + 1 < P.size() ? P[i + 1] : P[i];
    const int steps = std::max(1, static_cast<int>(std::ceil(norm(b - a) / spacing)));
    const int last = i + 1 < P.size() ? steps : 1;
    for (int s = 0; s < last; ++s) samples.push_back(index.nearest(a + (b - a) * (static_cast<double>(s) / steps)));
  }
  if (samples.size() == 1) samples.push_back(samples.front());
  for (size_t i = 0; i + 1 < samples.size(); ++i) segments_.push_back({samples[i].point_mm, samples[i + 1].point_mm});

  // Chunks about one radius long, each flooding the surface it can reach.
  const int per_chunk = std::max(1, static_cast<int>(std::ceil(std::max(radius_mm_, spacing) / spacing)));
  const double limit = kGraphStretch * (2 * radius_mm_ + per_chunk * spacing) + 2 * gate_slack_mm_;
  for (size_t first = 0; first < segments_.size(); first += static_cast<size_t>(per_chunk)) {
    const size_t last = std::min(segments_.size(), first + static_cast<size_t>(per_chunk));
    chunks_.push_back({static_cast<int>(first), static_cast<int>(last)});
    std::vector<float> dist(V.size(), kUnreached);
    using Item = std::pair<float, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> heap;
    for (size_t s = first; s <= last && s < samples.size(); ++s) {
      const MeshHit& h = samples[s];
      if (h.triangle < 0) continue;
      for (int v : surface.triangles_3d()[static_cast<size_t>(h.triangle)]) {
        const float d = static_cast<float>(norm(V[static_cast<size_t>(v)] - h.point_mm));
        if (d < dist[static_cast<size_t>(v)]) {
          dist[static_cast<size_t>(v)] = d;
          heap.push({d, v});
        }
      }
    }
    while (!heap.empty()) {
      const auto [d, v] = heap.top();
      heap.pop();
      if (d > dist[static_cast<size_t>(v)] || d > limit) continue;
      for (const auto& [w, len] : adj[static_cast<size_t>(v)]) {
        const float nd = d + len;
        if (nd < dist[static_cast<size_t>(w)]) {
          dist[static_cast<size_t>(w)] = nd;
          heap.push({nd, w});
        }
      }
    }
    chunk_distance_.push_back(std::move(dist));
  }
}

double StrokeField::reach(int chunk, int piece, const ChartLocation& loc) const {
  if (loc.triangle < 0) return kUnreached;
  const GarmentPiece& gp = *surface_.chart(piece).piece;
  const auto& tri = gp.mesh.triangles[static_cast<size_t>(loc.triangle)];
  const auto& dist = chunk_distance_[static_cast<size_t>(chunk)];
  double best = kUnreached;
  // The nearest reached corner plus the way across the triangle bounds the surface distance.
  for (int k = 0; k < 3; ++k) {
    const size_t v3 = static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(tri[static_cast<size_t>(k)])]);
    best = std::min(best, static_cast<double>(dist[v3]));
  }
  return best;
}

void StrokeField::candidates(const std::array<int, 3>& piece, const std::array<ChartLocation, 3>& loc,
                             const std::array<Vec3, 3>& c, std::vector<int>& out) const {
  const double diam = std::max({norm(c[0] - c[1]), norm(c[1] - c[2]), norm(c[2] - c[0])});
  const Vec3 centre = (c[0] + c[1] + c[2]) / 3.0;
  for (size_t ch = 0; ch < chunks_.size(); ++ch) {
    double r = kUnreached;
    for (int k = 0; k < 3; ++k) r = std::min(r, reach(static_cast<int>(ch), piece[static_cast<size_t>(k)], loc[static_cast<size_t>(k)]));
    if (!(r <= kGraphStretch * (radius_mm_ + diam) + gate_slack_mm_)) continue;
    // Reachable along the surface: keep the chunk's segments that come near in space as well.
    for (int s = chunks_[ch][0]; s < chunks_[ch][1]; ++s) {
      const StrokeSegment& seg = segments_[static_cast<size_t>(s)];
      if (point_segment_distance(centre, seg.a, seg.b) <= radius_mm_ + diam + 1.0) out.push_back(s);
    }
  }
}

double StrokeField::coverage(double d, double pixel_mm) const {
  // Full strength inside hardness * radius, a smooth falloff to the radius; a hard edge is
  // still spread over one pixel so it is anti-aliased.
  double inner = hardness_ * radius_mm_, outer = radius_mm_;
  if (outer - inner < pixel_mm) {
    inner = radius_mm_ - 0.5 * pixel_mm;
    outer = radius_mm_ + 0.5 * pixel_mm;
  }
  if (d <= inner) return 1;
  if (d >= outer) return 0;
  const double x = (outer - d) / (outer - inner);
  return x * x * (3 - 2 * x);
}

}  // namespace tp::geometry::internal
