// geometry/body/body_sdf.cpp: narrow-band nearest-triangle grid with winding-number inside flags.
#include "geometry/body/body_sdf.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "geometry/common/closest_point_on_triangle.h"
#include "geometry/common/thread_pool.h"
#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

// Grids larger than this are refused (memory); 64 M nodes is about 320 MB.
constexpr size_t kMaxNodes = size_t{64} << 20;
// The nearest-feature walk stops after this many moves (it usually needs one or two).
constexpr int kMaxWalkSteps = 16;

double angle_between(Vec3 u, Vec3 v) {
  double nu = norm(u), nv = norm(v);
  if (nu == 0 || nv == 0) return 0;
  return std::acos(std::clamp(dot(u, v) / (nu * nv), -1.0, 1.0));
}

}  // namespace

Result<BodySdf> BodySdf::build(BodyMesh body, double spacing_mm, int band_cells) {
  if (body.triangles.empty() || body.vertices_mm.empty())
    return fail(ErrorCode::kInvalidArgument, "body '" + body.name + "' has no triangles");
  if (!(spacing_mm > 0.5) || band_cells < 1)
    return fail(ErrorCode::kInvalidArgument, "body grid spacing must be > 0.5 mm and band >= 1 cell");
  BodySdf s;
  s.mesh_ = std::move(body);
  s.box_ = bounds(s.mesh_);
  s.spacing_mm_ = spacing_mm;
  s.band_cells_ = band_cells;
  const auto& V = s.mesh_.vertices_mm;
  const auto& F = s.mesh_.triangles;
  const int nv = static_cast<int>(V.size()), nf = static_cast<int>(F.size());
  for (const auto& t : F)
    for (int v : t)
      if (v < 0 || v >= nv) return fail(ErrorCode::kInvalidArgument, "body '" + s.mesh_.name + "' has a triangle index out of range");

  // Pseudo-normals (Baerentzen and Aanaes): face, angle-weighted vertex, summed edge normals.
  s.face_normal_.resize(nf);
  s.vertex_normal_.assign(nv, Vec3{});
  s.edge_normal_.assign(nf, {});
  std::unordered_map<uint64_t, Vec3> edge_sum;
  edge_sum.reserve(static_cast<size_t>(nf) * 2);
  const auto edge_key = [](int a, int b) {
    return (static_cast<uint64_t>(std::min(a, b)) << 32) | static_cast<uint32_t>(std::max(a, b));
  };
  for (int f = 0; f < nf; ++f) {
    const auto& t = F[f];
    Vec3 n = normalized(cross(V[t[1]] - V[t[0]], V[t[2]] - V[t[0]]));
    s.face_normal_[f] = n;
    for (int k = 0; k < 3; ++k) {
      int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      s.vertex_normal_[a] += n * angle_between(V[b] - V[a], V[c] - V[a]);
      edge_sum[edge_key(a, b)] += n;
    }
  }
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) s.edge_normal_[f][k] = edge_sum[edge_key(F[f][k], F[f][(k + 1) % 3])];
  // Faces around each vertex (for the nearest-feature walk), and degenerate faces to skip.
  s.degenerate_.resize(nf);
  s.vertex_face_start_.assign(nv + 1, 0);
  for (int f = 0; f < nf; ++f) {
    s.degenerate_[f] = norm(s.face_normal_[f]) == 0;
    for (int v : F[f]) ++s.vertex_face_start_[v + 1];
  }
  for (int v = 0; v < nv; ++v) s.vertex_face_start_[v + 1] += s.vertex_face_start_[v];
  s.vertex_faces_.resize(s.vertex_face_start_[nv]);
  {
    std::vector<int32_t> fill(s.vertex_face_start_.begin(), s.vertex_face_start_.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int v : F[f]) s.vertex_faces_[fill[v]++] = f;
  }

  // Grid covering the body plus the band and two cells.
  const double h = spacing_mm;
  const double margin = (band_cells + 2) * h;
  s.origin_mm_ = s.box_.min - Vec3{margin, margin, margin};
  s.nx_ = static_cast<int>(std::ceil((s.box_.max.x - s.box_.min.x + 2 * margin) / h)) + 1;
  s.ny_ = static_cast<int>(std::ceil((s.box_.max.y - s.box_.min.y + 2 * margin) / h)) + 1;
  s.nz_ = static_cast<int>(std::ceil((s.box_.max.z - s.box_.min.z + 2 * margin) / h)) + 1;
  const size_t nodes = static_cast<size_t>(s.nx_) * s.ny_ * s.nz_;
  if (nodes > kMaxNodes) return fail(ErrorCode::kInvalidArgument, "body grid too large; raise the spacing");
  s.node_triangle_.assign(nodes, -1);
  s.node_inside_.assign(nodes, 0);

  // Exact nearest triangle for nodes within the band, in two z slabs on two threads.
  s.node_distance_.assign(nodes, static_cast<float>(s.band_mm()));
  const auto band_pass = [&](int k_begin, int k_end) {
    float* best = s.node_distance_.data() + static_cast<size_t>(k_begin) * s.nx_ * s.ny_;
    for (int f = 0; f < nf; ++f) {
      if (s.degenerate_[f]) continue;
      const auto& t = F[f];
      Box3 tb;
      for (int v : t) tb.add(V[v]);
      const auto lo = [&](double x, double o) { return static_cast<int>(std::floor((x - o) / h)) - band_cells; };
      const auto hi = [&](double x, double o) { return static_cast<int>(std::ceil((x - o) / h)) + band_cells; };
      int i0 = std::max(lo(tb.min.x, s.origin_mm_.x), 0), i1 = std::min(hi(tb.max.x, s.origin_mm_.x), s.nx_ - 1);
      int j0 = std::max(lo(tb.min.y, s.origin_mm_.y), 0), j1 = std::min(hi(tb.max.y, s.origin_mm_.y), s.ny_ - 1);
      int k0 = std::max(lo(tb.min.z, s.origin_mm_.z), k_begin), k1 = std::min(hi(tb.max.z, s.origin_mm_.z), k_end - 1);
      for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            Vec3 p = s.origin_mm_ + Vec3{double(i), double(j), double(k)} * h;
            TriangleClosestPoint q = closest_point_on_triangle(p, V[t[0]], V[t[1]], V[t[2]]);
            float d = static_cast<float>(norm(p - q.point_mm));
            size_t local = (static_cast<size_t>(k - k_begin) * s.ny_ + j) * s.nx_ + i;
            if (d < best[local]) {
              best[local] = d;
              s.node_triangle_[s.node(i, j, k)] = f;
            }
          }
    }
  };
  {
    const int mid = s.nz_ / 2;
    ThreadPool pool(2);
    pool.parallel_for(2, [&](int slab, int) { slab == 0 ? band_pass(0, mid) : band_pass(mid, s.nz_); });
  }

  // Inside flags: winding number along +z rays through each (x, y) column. Columns are shifted
  // by a tiny irrational fraction of a cell so that no ray passes exactly through an edge.
  const double ox = 1e-3 * 0.6180339887 * h, oy = 1e-3 * 0.3819660113 * h;
  std::vector<std::vector<std::pair<double, int>>> columns(static_cast<size_t>(s.nx_) * s.ny_);
  for (int f = 0; f < nf; ++f) {
    const auto& t = F[f];
    Vec3 a = V[t[0]], b = V[t[1]], c = V[t[2]];
    double area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area2 == 0) continue;
    int i0 = std::max(static_cast<int>(std::floor((std::min({a.x, b.x, c.x}) - s.origin_mm_.x - ox) / h)), 0);
    int i1 = std::min(static_cast<int>(std::ceil((std::max({a.x, b.x, c.x}) - s.origin_mm_.x - ox) / h)), s.nx_ - 1);
    int j0 = std::max(static_cast<int>(std::floor((std::min({a.y, b.y, c.y}) - s.origin_mm_.y - oy) / h)), 0);
    int j1 = std::min(static_cast<int>(std::ceil((std::max({a.y, b.y, c.y}) - s.origin_mm_.y - oy) / h)), s.ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        double x = s.origin_mm_.x + i * h + ox, y = s.origin_mm_.y + j * h + oy;
        double w0 = (b.x - x) * (c.y - y) - (b.y - y) * (c.x - x);
        double w1 = (c.x - x) * (a.y - y) - (c.y - y) * (a.x - x);
        double w2 = (a.x - x) * (b.y - y) - (a.y - y) * (b.x - x);
        bool in = area2 > 0 ? (w0 > 0 && w1 > 0 && w2 > 0) : (w0 < 0 && w1 < 0 && w2 < 0);
        if (!in) continue;
        double z = (w0 * a.z + w1 * b.z + w2 * c.z) / area2;
        // Normal facing -z: the ray enters the body (+1); facing +z: it leaves (-1).
        columns[static_cast<size_t>(j) * s.nx_ + i].push_back({z, area2 > 0 ? -1 : +1});
      }
  }
  for (int j = 0; j < s.ny_; ++j)
    for (int i = 0; i < s.nx_; ++i) {
      auto& col = columns[static_cast<size_t>(j) * s.nx_ + i];
      if (col.empty()) continue;
      std::sort(col.begin(), col.end());
      int winding = 0;
      size_t c = 0;
      for (int k = 0; k < s.nz_; ++k) {
        double z = s.origin_mm_.z + k * h;
        while (c < col.size() && col[c].first < z) winding += col[c++].second;
        s.node_inside_[s.node(i, j, k)] = winding > 0;
      }
    }
  // Node distances: exact in the band, clamped to it beyond; negative inside.
  for (size_t n = 0; n < nodes; ++n) {
    float d = std::min(s.node_distance_[n], static_cast<float>(s.band_mm()));
    s.node_distance_[n] = s.node_inside_[n] ? -d : d;
  }
  return s;
}

double BodySdf::approx_distance_mm(Vec3 p) const {
  Vec3 g = (p - origin_mm_) / spacing_mm_;
  int i = static_cast<int>(std::floor(g.x)), j = static_cast<int>(std::floor(g.y)), k = static_cast<int>(std::floor(g.z));
  if (i < 0 || j < 0 || k < 0 || i >= nx_ - 1 || j >= ny_ - 1 || k >= nz_ - 1) return band_mm() + 2 * spacing_mm_;
  double fx = g.x - i, fy = g.y - j, fz = g.z - k, d = 0;
  for (int c = 0; c < 8; ++c) {
    double w = ((c & 1) ? fx : 1 - fx) * ((c & 2) ? fy : 1 - fy) * ((c & 4) ? fz : 1 - fz);
    d += w * node_distance_[node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
  }
  return d;
}

BodySdf::Hit BodySdf::query(Vec3 p) const {
  Hit hit;
  const double h = spacing_mm_;
  Vec3 g = (p - origin_mm_) / h;
  int i = static_cast<int>(std::floor(g.x)), j = static_cast<int>(std::floor(g.y)), k = static_cast<int>(std::floor(g.z));
  if (i < 0 || j < 0 || k < 0 || i >= nx_ - 1 || j >= ny_ - 1 || k >= nz_ - 1) {
    hit.distance_mm = band_mm() + 2 * h;  // outside the grid: far outside the body
    return hit;
  }
  std::array<int32_t, 8> cand{};
  int nc = 0, inside_votes = 0;
  for (int c = 0; c < 8; ++c) {
    size_t n = node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
    inside_votes += node_inside_[n];
    int32_t t = node_triangle_[n];
    if (t >= 0 && std::find(cand.begin(), cand.begin() + nc, t) == cand.begin() + nc) cand[nc++] = t;
  }
  if (nc == 0) {
    hit.distance_mm = inside_votes >= 4 ? -band_mm() : band_mm();
    return hit;
  }
  double best = 1e300;
  TriangleClosestPoint best_q;
  int best_t = -1;
  const auto try_face = [&](int32_t f) {
    if (degenerate_[f]) return false;
    const auto& t = mesh_.triangles[f];
    TriangleClosestPoint q =
        closest_point_on_triangle(p, mesh_.vertices_mm[t[0]], mesh_.vertices_mm[t[1]], mesh_.vertices_mm[t[2]]);
    double d = norm(p - q.point_mm);
    if (d >= best) return false;
    best = d, best_q = q, best_t = f;
    return true;
  };
  for (int c = 0; c < nc; ++c) try_face(cand[c]);
  // Walk to nearer faces around the nearest feature (its vertex, or its edge's two vertices)
  // until the nearest point lies inside a face or nothing nearer is found.
  for (int step = 0; step < kMaxWalkSteps && best_t >= 0 && best_q.feature != 0; ++step) {
    const int from = best_t;
    const auto& t = mesh_.triangles[from];
    int va = -1, vb = -1;
    if (best_q.feature >= 4) va = t[best_q.feature - 4];
    else va = t[best_q.feature - 1], vb = t[best_q.feature % 3];
    for (int v : {va, vb})
      if (v >= 0)
        for (int32_t k = vertex_face_start_[v]; k < vertex_face_start_[v + 1]; ++k) try_face(vertex_faces_[k]);
    if (best_t == from) break;
  }
  if (best_t < 0) {
    hit.distance_mm = inside_votes >= 4 ? -band_mm() : band_mm();
    return hit;
  }
  const auto& t = mesh_.triangles[best_t];
  Vec3 pseudo = best_q.feature == 0   ? face_normal_[best_t]
                : best_q.feature <= 3 ? edge_normal_[best_t][best_q.feature - 1]
                                      : vertex_normal_[t[best_q.feature - 4]];
  Vec3 away = p - best_q.point_mm;
  double sign = dot(away, pseudo) >= 0 ? 1.0 : -1.0;
  hit.near = true;
  hit.distance_mm = sign * best;
  hit.closest_mm = best_q.point_mm;
  hit.normal = best > kSamePoint_mm ? away * (sign / best) : normalized(pseudo);
  return hit;
}

}  // namespace tp::geometry
