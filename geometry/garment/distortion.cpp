// geometry/garment/distortion.cpp: strain, area change, seam lengths and body clearance of a garment.
#include "geometry/garment/distortion.h"
#include "geometry/common/segment.h"
#include "geometry/common/tolerances.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry {
namespace {

// A mesh vertex lies on a span when its arc position is within this of [from, to].
constexpr double kSpanTolMm = 0.05;

// Singular values of the 3x2 map taking the 2D triangle (p) onto the 3D one (x).
std::pair<double, double> singular_values(const std::array<Vec2, 3>& p, const std::array<Vec3, 3>& x) {
  Vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
  double det = cross(e1, e2);
  if (std::abs(det) < kParallelDeterminant) return {1, 1};
  Vec3 d1 = x[1] - x[0], d2 = x[2] - x[0];
  // F = [d1 d2] Dm^-1.
  double i00 = e2.y / det, i01 = -e2.x / det, i10 = -e1.y / det, i11 = e1.x / det;
  Vec3 f0 = d1 * i00 + d2 * i10, f1 = d1 * i01 + d2 * i11;
  double a = dot(f0, f0), b = dot(f0, f1), c = dot(f1, f1);
  double tr = a + c, disc = std::sqrt(std::max((a - c) * (a - c) / 4 + b * b, 0.0));
  return {std::sqrt(std::max(tr / 2 + disc, 0.0)), std::sqrt(std::max(tr / 2 - disc, 0.0))};
}

// Arc length along `pl` of the point of `pl` nearest to q.
double arc_position(const std::vector<Vec2>& pl, Vec2 q) {
  double best = 1e300, pos = 0, acc = 0;
  for (size_t i = 1; i < pl.size(); ++i) {
    Vec2 d = pl[i] - pl[i - 1];
    double len = norm(d);
    double t = len > 0 ? std::clamp(dot(q - pl[i - 1], d) / (len * len), 0.0, 1.0) : 0.0;
    double dist = norm(pl[i - 1] + d * t - q);
    if (dist < best) best = dist, pos = acc + t * len;
    acc += len;
  }
  return pos;
}

// Chart vertices of a span, in order from its start to its end: the edge's mesh vertices whose
// arc-length position on the pattern edge lies within [from, to].
std::vector<int> span_vertices(const Pattern& pattern, const Garment& g, const EdgeSpan& sp) {
  const PieceMesh& m = g.pieces[sp.piece].mesh;
  const Edge& edge = pattern.pieces[sp.piece].edges[sp.edge];
  double to = sp.to_mm < 0 ? edge_length_mm(edge) : sp.to_mm;
  std::vector<int> out;
  for (int v : m.edge_vertices[sp.edge]) {
    double s = arc_position(edge.points_mm, m.vertices_mm[v]);
    if (s >= sp.from_mm - kSpanTolMm && s <= to + kSpanTolMm) out.push_back(v);
  }
  return out;
}

// Length of the polyline through the chart vertices `vs`, in 2D (mesh) or 3D (garment).
double chart_length(const GarmentPiece& gp, const std::vector<int>& vs) {
  double l = 0;
  for (size_t k = 1; k < vs.size(); ++k) l += norm(gp.mesh.vertices_mm[vs[k]] - gp.mesh.vertices_mm[vs[k - 1]]);
  return l;
}

double sewn_length(const Garment& g, const GarmentPiece& gp, const std::vector<int>& vs) {
  double l = 0;
  for (size_t k = 1; k < vs.size(); ++k) l += norm(g.vertices_mm[gp.vertex_3d[vs[k]]] - g.vertices_mm[gp.vertex_3d[vs[k - 1]]]);
  return l;
}

// The area-weighted 95th percentile of (strain, area) pairs; sorts them.
double weighted_p95(std::vector<std::pair<double, double>>& strain_area) {
  double total = 0;
  for (auto [s, a] : strain_area) total += a;
  if (!(total > 0)) return 0;
  std::sort(strain_area.begin(), strain_area.end());
  double acc = 0, p95 = 0;
  for (auto [s, a] : strain_area) {
    acc += a;
    p95 = s;
    if (acc >= 0.95 * total) break;
  }
  return p95;
}

// Per piece, the 2D seam polylines (span vertices in order) of the marked eased stitches.
std::vector<std::vector<std::vector<Vec2>>> eased_spans(const Pattern& pattern, const Garment& g) {
  std::vector<std::vector<std::vector<Vec2>>> out(g.pieces.size());
  for (const Stitch& st : pattern.stitches) {
    if (!(st.ease_ratio > 0)) continue;
    for (const EdgeSpan* sp : {&st.a, &st.b}) {
      std::vector<Vec2> line;
      for (int v : span_vertices(pattern, g, *sp)) line.push_back(g.pieces[sp->piece].mesh.vertices_mm[v]);
      if (!line.empty()) out[sp->piece].push_back(std::move(line));
    }
  }
  return out;
}

bool in_eased_region(const std::vector<std::vector<Vec2>>& lines, Vec2 q) {
  for (const auto& line : lines) {
    // A span of one vertex is a point: its segment to itself.
    for (size_t k = 0; k < line.size(); ++k)
      if (distance_to_segment(q, line[k], line[k + 1 < line.size() ? k + 1 : k]) <= kEasedRegionMm) return true;
  }
  return false;
}

}  // namespace

DistortionReport measure_distortion(const Pattern& pattern, const Garment& g, const BodySdf* body) {
  DistortionReport r;
  r.vertices = static_cast<int>(g.vertices_mm.size());
  std::vector<std::pair<double, double>> strain_area, plain, eased;  // (strain, 2D area)
  double area2 = 0, area3 = 0, eased_area2 = 0;
  const auto eased_lines = eased_spans(pattern, g);
  for (size_t pi = 0; pi < g.pieces.size(); ++pi) {
    const GarmentPiece& gp = g.pieces[pi];
    for (const auto& t : gp.mesh.triangles) {
      std::array<Vec2, 3> p{gp.mesh.vertices_mm[t[0]], gp.mesh.vertices_mm[t[1]], gp.mesh.vertices_mm[t[2]]};
      std::array<Vec3, 3> x{g.vertices_mm[gp.vertex_3d[t[0]]], g.vertices_mm[gp.vertex_3d[t[1]]],
                            g.vertices_mm[gp.vertex_3d[t[2]]]};
      double a2 = 0.5 * std::abs(cross(p[1] - p[0], p[2] - p[0]));
      double a3 = 0.5 * norm(cross(x[1] - x[0], x[2] - x[0]));
      auto [s1, s2] = singular_values(p, x);
      strain_area.push_back({std::max(std::abs(s1 - 1), std::abs(s2 - 1)), a2});
      const bool in_eased = in_eased_region(eased_lines[pi], (p[0] + p[1] + p[2]) / 3.0);
      (in_eased ? eased : plain).push_back(strain_area.back());
      if (in_eased) eased_area2 += a2;
      area2 += a2;
      area3 += a3;
      ++r.triangles;
    }
  }
  if (area2 > 0) {
    double sum = 0;
    for (auto [s, a] : strain_area) sum += s * a;
    r.strain_mean = sum / area2;
    r.strain_p95 = weighted_p95(strain_area);
    r.strain_max = strain_area.back().first;
    r.strain_p95_plain = weighted_p95(plain);
    r.strain_p95_eased = weighted_p95(eased);
    r.eased_area_fraction = eased_area2 / area2;
    r.area_change = (area3 - area2) / area2;
  }

  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    const Stitch& st = pattern.stitches[s];
    SeamLength sl;
    sl.stitch = static_cast<int>(s);
    // Lengths along the meshed seam (chords between its vertices) in 2D on both pieces and in
    // 3D, so curved seams are compared like with like.
    std::vector<int> va = span_vertices(pattern, g, st.a), vb = span_vertices(pattern, g, st.b);
    sl.a_mm = chart_length(g.pieces[st.a.piece], va);
    sl.b_mm = chart_length(g.pieces[st.b.piece], vb);
    sl.sewn_mm = sewn_length(g, g.pieces[st.a.piece], va);
    double ref = std::max(sl.a_mm, sl.b_mm);
    sl.diff = ref > 0 ? std::max({std::abs(sl.sewn_mm - sl.a_mm), std::abs(sl.sewn_mm - sl.b_mm), std::abs(sl.a_mm - sl.b_mm)}) / ref : 0;
    sl.eased = st.ease_ratio > 0;
    r.seam_len_diff_max = std::max(r.seam_len_diff_max, sl.diff);
    if (!sl.eased) r.seam_len_diff_max_plain = std::max(r.seam_len_diff_max_plain, sl.diff);
    r.seams.push_back(sl);
  }

  if (body) {
    r.min_clearance_mm = 1e300;
    for (const Vec3& v : g.vertices_mm) {
      double d = body->query(v).distance_mm;
      r.inside_body += d < 0;
      r.min_clearance_mm = std::min(r.min_clearance_mm, d);
    }
  }
  return r;
}

}  // namespace tp::geometry
