// geometry/sewing/internal/self_collision.cpp: spatial hash broad phase and the point-triangle and
// edge-edge projections that keep cloth from passing through itself.
#include "geometry/sewing/internal/self_collision.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "geometry/common/closest_point_on_triangle.h"
#include "geometry/common/tolerances.h"

namespace tp::geometry::internal {
namespace {

/// Primitives of one piece closer than this many mean edges in the pattern are not paired.
constexpr double kRestNeighbourEdges = 1.5;
/// A pair whose bound on its distance clears the thickness by this much (mm) is skipped before
/// its closest points are found (the margin covers the bound's rounding, so the result is the
/// one the full test gives).
constexpr double kSkipMargin_mm = 1e-6;

// A dense spatial hash (Teschner et al. 2003): entries counted into a fixed table by cell hash,
// in buffers kept from the last search.
class SpatialHash {
 public:
  SpatialHash(double cell_mm, size_t entries, SelfCollisionScratch::Hash& buf) : cell_(cell_mm), b_(buf) {
    size_t slots = 1024;
    while (slots < entries * 2) slots *= 2;
    b_.start.assign(slots + 1, 0);
  }

  std::array<int, 3> cell(Vec3 p) const {
    return {static_cast<int>(std::floor(p.x / cell_)), static_cast<int>(std::floor(p.y / cell_)),
            static_cast<int>(std::floor(p.z / cell_))};
  }
  size_t slot(int i, int j, int k) const {
    const uint64_t h = (static_cast<uint64_t>(static_cast<uint32_t>(i)) * 92837111u) ^
                       (static_cast<uint64_t>(static_cast<uint32_t>(j)) * 689287499u) ^
                       (static_cast<uint64_t>(static_cast<uint32_t>(k)) * 283923481u);
    return static_cast<size_t>((h ^ (h >> 29)) & (b_.start.size() - 2));
  }
  // Two passes: count() every entry's cells, then fill() them in the same order.
  void count(size_t s) { ++b_.start[s]; }
  void finish_counts() {
    size_t sum = 0;
    for (auto& c : b_.start) {
      size_t v = c;
      c = sum;
      sum += v;
    }
    b_.ids.resize(sum);
    b_.fill.assign(b_.start.begin(), b_.start.end());
  }
  void fill(size_t s, int id) { b_.ids[b_.fill[s]++] = id; }
  template <class Fn>
  void visit(size_t s, Fn&& fn) const {
    for (size_t k = b_.start[s]; k < b_.start[s + 1]; ++k) fn(b_.ids[k]);
  }
  // Where slot s's next entry goes, while filling (a slot's entries ascend: fill() runs in id order).
  size_t fill_end(size_t s) const { return b_.fill[s]; }
  // Slot s's entries from table position `from` on, in their order.
  template <class Fn>
  void visit_from(size_t s, size_t from, Fn&& fn) const {
    for (size_t k = from; k < b_.start[s + 1]; ++k) fn(b_.ids[k]);
  }

 private:
  double cell_;
  SelfCollisionScratch::Hash& b_;
};

// Closest point to p on triangle (a, b, c) as barycentric weights.
std::array<double, 3> closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  return closest_point_on_triangle(p, a, b, c).bary;
}

// Closest points of segments p0-p1 and q0-q1 as parameters (s, t) in [0, 1].
std::array<double, 2> closest_on_segments(Vec3 p0, Vec3 p1, Vec3 q0, Vec3 q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  if (a < 1e-18 || e < 1e-18) return {0, 0};
  const double c = dot(d1, r), b = dot(d1, d2), denom = a * e - b * b;
  double s = denom > kParallelDeterminant * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
  else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
  return {s, t};
}

Vec3 triangle_normal(const std::vector<Vec3>& x, const RestTriangle& t) {
  return normalized(cross(x[t.v[1]] - x[t.v[0]], x[t.v[2]] - x[t.v[0]]));
}

// Visits the hash slots of every cell the box [lo, hi] covers.
template <class Fn>
void for_cells(const SpatialHash& h, Vec3 lo, Vec3 hi, Fn&& fn) {
  const auto a = h.cell(lo), b = h.cell(hi);
  for (int i = a[0]; i <= b[0]; ++i)
    for (int j = a[1]; j <= b[1]; ++j)
      for (int k = a[2]; k <= b[2]; ++k) fn(h.slot(i, j, k));
}

// Runs fn(begin, end, list, worker) over fixed chunks of [0, n) on the pool, each chunk into its
// own list, and appends the lists to `out` in chunk order: the result does not depend on the
// thread count.
template <class T, class Fn>
void in_chunks(size_t n, ThreadPool* pool, std::vector<std::vector<T>>& parts, std::vector<T>& out, Fn&& fn) {
  constexpr size_t kChunk = 1024;
  const int chunks = static_cast<int>((n + kChunk - 1) / kChunk);
  if (pool == nullptr || pool->size() == 1 || chunks <= 1) {
    fn(0, n, out, 0);
    return;
  }
  if (parts.size() < static_cast<size_t>(chunks)) parts.resize(chunks);
  pool->parallel_for(chunks, [&](int c, int worker) {
    parts[c].clear();
    fn(c * kChunk, std::min(n, (c + 1) * kChunk), parts[c], worker);
  });
  for (int c = 0; c < chunks; ++c) out.insert(out.end(), parts[c].begin(), parts[c].end());
}

}  // namespace

SelfCollisionPairs find_self_collision_pairs(const ClothModel& cloth, const std::vector<Vec3>& x, double margin_mm,
                                             ThreadPool* pool, SelfCollisionScratch* scratch) {
  SelfCollisionPairs out;
  SelfCollisionScratch local;
  SelfCollisionScratch& sc = scratch ? *scratch : local;
  const int workers = pool ? pool->size() : 1;
  const size_t stamp_size = std::max(x.size(), cloth.edges.size());
  if (sc.stamps.size() < static_cast<size_t>(workers)) sc.stamps.resize(workers), sc.found.resize(workers);
  for (int w = 0; w < workers; ++w)
    if (sc.stamps[w].size() != stamp_size) sc.stamps[w].assign(stamp_size, 0);
  // A query's stamp: this search's two generations (point-triangle, edge-edge) and its index.
  const uint64_t pt_gen = (++sc.generation) << 32, ee_gen = (++sc.generation) << 32;
  // Vertices of one weld group count as one (seam sides being sewn may meet).
  auto group = [&](int v) { return cloth.weld_group.empty() ? v : cloth.weld_group[v]; };
  // Vertex u is in the seam neighbourhood of v (or v in u's).
  auto seam_near = [&](int v, int u) {
    if (cloth.seam_near.empty()) return false;
    const auto& nv = cloth.seam_near[v];
    const auto& nu = cloth.seam_near[u];
    return (!nv.empty() && std::binary_search(nv.begin(), nv.end(), group(u))) ||
           (!nu.empty() && std::binary_search(nu.begin(), nu.end(), group(v)));
  };
  // Vertices v and u lie in the zones of the two sides of one open stitch.
  auto opposite_zones = [&](int v, int u) {
    if (cloth.seam_zone_active.empty()) return false;
    const auto& zu = cloth.seam_zone_active[u];
    if (zu.empty()) return false;
    for (int c : cloth.seam_zone_active[v])
      if (std::binary_search(zu.begin(), zu.end(), c ^ 1)) return true;
    return false;
  };
  // Primitives of one piece whose corners are within kRestNeighbourEdges mean edges in the
  // pattern are mesh neighbours: they only meet if the triangles between them fold flat, which
  // bending and the pairs farther out keep from happening. Left out, the drape of shirt_mean at
  // 10,174 vertices has 90 % fewer pairs.
  const double cull2 = std::pow(kRestNeighbourEdges * cloth.mean_edge_mm, 2);
  const bool can_cull = cloth.vertex_rest_mm.size() == x.size() && cloth.vertex_piece.size() == x.size();
  auto rest_neighbours = [&](std::initializer_list<int> a, std::initializer_list<int> b) {
    if (!can_cull) return false;
    const int piece = cloth.vertex_piece[*a.begin()];
    for (int v : a)
      if (cloth.vertex_piece[v] != piece) return false;
    for (int v : b)
      if (cloth.vertex_piece[v] != piece) return false;
    for (int u : a)
      for (int v : b) {
        const Vec2 d = cloth.vertex_rest_mm[u] - cloth.vertex_rest_mm[v];
        if (d.x * d.x + d.y * d.y <= cull2) return true;
      }
    return false;
  };
  const double cell = std::max(cloth.mean_edge_mm, 2 * margin_mm);
  const Vec3 pad{margin_mm, margin_mm, margin_mm};

  // Point-triangle: vertices hashed by cell, each triangle's padded box looked up.
  SpatialHash vh(cell, x.size(), sc.vertices);
  for (const Vec3& p : x) { auto c = vh.cell(p); vh.count(vh.slot(c[0], c[1], c[2])); }
  vh.finish_counts();
  for (size_t i = 0; i < x.size(); ++i) { auto c = vh.cell(x[i]); vh.fill(vh.slot(c[0], c[1], c[2]), static_cast<int>(i)); }
  // Visited stamps dedupe a query's hits without sorting (the order stays the cells' order).
  // Ranges of triangles (and of edges below) run on their own threads into their own lists,
  // joined in range order: the pairs and their order do not depend on the thread count.
  auto point_triangle = [&](size_t f0, size_t f1, std::vector<PointTrianglePair>& pt_out, int worker) {
    std::vector<uint64_t>& stamp_v = sc.stamps[worker];
    std::vector<int>& found = sc.found[worker];
    for (size_t f = f0; f < f1; ++f) {
      const RestTriangle& t = cloth.triangles[f];
      const Vec3 a = x[t.v[0]], b = x[t.v[1]], c = x[t.v[2]];
      const Vec3 lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
      const Vec3 hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
      const Vec3 plo = lo - pad, phi = hi + pad;
      // Most vertices the cells hold are outside the box: left out before the stamp.
      found.clear();
      for_cells(vh, plo, phi, [&](size_t s) {
        vh.visit(s, [&](int v) {
          const Vec3 q = x[v];
          if (q.x < plo.x || q.y < plo.y || q.z < plo.z || q.x > phi.x || q.y > phi.y || q.z > phi.z) return;
          if (stamp_v[v] != (pt_gen | f)) stamp_v[v] = pt_gen | f, found.push_back(v);
        });
      });
      Vec3 n{};
      bool have_normal = false;
      for (int v : found) {
        // The tests are filters, the cheapest first.
        const int gv = group(v);
        if (gv == group(t.v[0]) || gv == group(t.v[1]) || gv == group(t.v[2])) continue;
        if (rest_neighbours({v}, {t.v[0], t.v[1], t.v[2]})) continue;
        if (seam_near(v, t.v[0]) || seam_near(v, t.v[1]) || seam_near(v, t.v[2])) continue;
        if (opposite_zones(v, t.v[0]) || opposite_zones(v, t.v[1]) || opposite_zones(v, t.v[2])) continue;
        const auto w = closest_on_triangle(x[v], a, b, c);
        const Vec3 q = a * w[0] + b * w[1] + c * w[2];
        if (norm(x[v] - q) >= margin_mm) continue;
        if (!have_normal) n = triangle_normal(x, t), have_normal = true;
        pt_out.push_back({v, static_cast<int>(f), dot(x[v] - q, n) >= 0 ? 1.0 : -1.0});
      }
    }
  };
  in_chunks(cloth.triangles.size(), pool, sc.point_triangle_parts, out.point_triangle, point_triangle);

  // Edge-edge: edges hashed into every cell their padded box covers, then paired per cell.
  SpatialHash eh(cell, cloth.edges.size() * 4, sc.edges);
  // Boxes once per search: each edge's is read again for every edge sharing a cell with it.
  auto& boxes = sc.edge_boxes;
  boxes.resize(cloth.edges.size());
  for (size_t k = 0; k < cloth.edges.size(); ++k) {
    const Vec3 p = x[cloth.edges[k][0]], q = x[cloth.edges[k][1]];
    boxes[k] = {Vec3{std::min(p.x, q.x), std::min(p.y, q.y), std::min(p.z, q.z)} - pad * 0.5,
                Vec3{std::max(p.x, q.x), std::max(p.y, q.y), std::max(p.z, q.z)} + pad * 0.5};
    for_cells(eh, boxes[k][0], boxes[k][1], [&](size_t s) { eh.count(s); });
  }
  eh.finish_counts();
  // Where the edges above each edge begin in its cells' slots, noted as it goes in (the fill
  // runs in edge order): its query walks them without hashing its cells again or searching.
  sc.edge_cells_start.assign(cloth.edges.size() + 1, 0);
  sc.edge_cells_slot.clear();
  sc.edge_cells_above.clear();
  for (size_t k = 0; k < cloth.edges.size(); ++k) {
    sc.edge_cells_start[k] = sc.edge_cells_slot.size();
    for_cells(eh, boxes[k][0], boxes[k][1], [&](size_t s) {
      eh.fill(s, static_cast<int>(k));
      sc.edge_cells_slot.push_back(s);
    });
    // Two of k's cells in one slot hold k twice, side by side: the edges above start past both.
    for (size_t c = sc.edge_cells_start[k]; c < sc.edge_cells_slot.size(); ++c)
      sc.edge_cells_above.push_back(eh.fill_end(sc.edge_cells_slot[c]));
  }
  sc.edge_cells_start[cloth.edges.size()] = sc.edge_cells_slot.size();
  auto edge_edge = [&](size_t k0, size_t k1, std::vector<EdgeEdgePair>& ee_out, int worker) {
    std::vector<uint64_t>& stamp_e = sc.stamps[worker];
    for (size_t k = k0; k < k1; ++k) {
      const auto& ea = cloth.edges[k];
      const Vec3 lo = boxes[k][0], hi = boxes[k][1];
      const int a0 = group(ea[0]), a1 = group(ea[1]);
      // Each edge above k is tested where the cells first meet it (the stamp skips the rest).
      auto test = [&](int o) {
        const Vec3 olo = boxes[o][0], ohi = boxes[o][1];
        if (olo.x > hi.x || olo.y > hi.y || olo.z > hi.z || ohi.x < lo.x || ohi.y < lo.y || ohi.z < lo.z) return;
        const auto& eb = cloth.edges[o];
        const int b0 = group(eb[0]), b1 = group(eb[1]);
        if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) return;
        if (rest_neighbours({ea[0], ea[1]}, {eb[0], eb[1]})) return;
        if (seam_near(ea[0], eb[0]) || seam_near(ea[0], eb[1]) || seam_near(ea[1], eb[0]) || seam_near(ea[1], eb[1]))
          return;
        if (opposite_zones(ea[0], eb[0]) || opposite_zones(ea[0], eb[1]) || opposite_zones(ea[1], eb[0]) ||
            opposite_zones(ea[1], eb[1]))
          return;
        const auto st = closest_on_segments(x[ea[0]], x[ea[1]], x[eb[0]], x[eb[1]]);
        const Vec3 pa = x[ea[0]] * (1 - st[0]) + x[ea[1]] * st[0], pb = x[eb[0]] * (1 - st[1]) + x[eb[1]] * st[1];
        const double d = norm(pa - pb);
        if (d >= margin_mm || d < kSamePoint_mm) return;
        ee_out.push_back({static_cast<int>(k), o, (pa - pb) / d});
      };
      const uint64_t query = ee_gen | k;
      for (size_t c = sc.edge_cells_start[k]; c < sc.edge_cells_start[k + 1]; ++c)
        eh.visit_from(sc.edge_cells_slot[c], sc.edge_cells_above[c], [&](int o) {
          if (stamp_e[o] != query) stamp_e[o] = query, test(o);
        });
    }
  };
  in_chunks(cloth.edges.size(), pool, sc.edge_edge_parts, out.edge_edge, edge_edge);
  return out;
}

int resolve_self_collisions(const ClothModel& cloth, const SelfCollisionPairs& pairs, double thickness_mm,
                            std::vector<Vec3>& x) {
  const auto& w = cloth.inv_mass;
  int contacts = 0;
  for (const PointTrianglePair& pr : pairs.point_triangle) {
    const RestTriangle& t = cloth.triangles[pr.triangle];
    const Vec3 a = x[t.v[0]], b = x[t.v[1]], c = x[t.v[2]];
    const Vec3 n = triangle_normal(x, t);
    if (dot(n, n) == 0) continue;
    // Its height over the triangle's plane is the distance below wherever the vertex is over the
    // face: a pair a thickness away from the plane is not in contact (most are not, each substep).
    if (dot(x[pr.vertex] - a, n) * pr.side >= thickness_mm + kSkipMargin_mm) continue;
    const auto bc = closest_on_triangle(x[pr.vertex], a, b, c);
    // Only where the vertex is over the triangle's face; edges are the edge-edge pairs' part.
    if (bc[0] <= 0 || bc[1] <= 0 || bc[2] <= 0) continue;
    const Vec3 q = a * bc[0] + b * bc[1] + c * bc[2];
    const double dist = dot(x[pr.vertex] - q, n) * pr.side;
    if (dist >= thickness_mm) continue;
    ++contacts;
    const Vec3 dir = n * pr.side;
    const double wsum = w[pr.vertex] + w[t.v[0]] * bc[0] * bc[0] + w[t.v[1]] * bc[1] * bc[1] + w[t.v[2]] * bc[2] * bc[2];
    if (wsum <= 0) continue;
    const double lambda = (thickness_mm - dist) / wsum;
    x[pr.vertex] += dir * (w[pr.vertex] * lambda);
    for (int k = 0; k < 3; ++k) x[t.v[k]] -= dir * (w[t.v[k]] * bc[k] * lambda);
  }
  for (const EdgeEdgePair& pr : pairs.edge_edge) {
    const auto& ea = cloth.edges[pr.edge_a];
    const auto& eb = cloth.edges[pr.edge_b];
    // The closest points' separation along the pair's direction is at least the nearest ends'.
    const Vec3& sep = pr.separation;
    const double lo_a = std::min(dot(x[ea[0]], sep), dot(x[ea[1]], sep));
    const double hi_b = std::max(dot(x[eb[0]], sep), dot(x[eb[1]], sep));
    if (lo_a - hi_b >= thickness_mm + kSkipMargin_mm) continue;
    const auto st = closest_on_segments(x[ea[0]], x[ea[1]], x[eb[0]], x[eb[1]]);
    // Interior crossings only: endpoints against faces are the point-triangle pairs' part.
    if (st[0] <= 0 || st[0] >= 1 || st[1] <= 0 || st[1] >= 1) continue;
    const Vec3 pa = x[ea[0]] * (1 - st[0]) + x[ea[1]] * st[0], pb = x[eb[0]] * (1 - st[1]) + x[eb[1]] * st[1];
    const double dist = dot(pa - pb, pr.separation);
    if (dist >= thickness_mm) continue;
    ++contacts;
    const double wa0 = w[ea[0]] * (1 - st[0]), wa1 = w[ea[1]] * st[0], wb0 = w[eb[0]] * (1 - st[1]), wb1 = w[eb[1]] * st[1];
    const double wsum = wa0 * (1 - st[0]) + wa1 * st[0] + wb0 * (1 - st[1]) + wb1 * st[1];
    if (wsum <= 0) continue;
    const double lambda = (thickness_mm - dist) / wsum;
    x[ea[0]] += pr.separation * (wa0 * lambda);
    x[ea[1]] += pr.separation * (wa1 * lambda);
    x[eb[0]] -= pr.separation * (wb0 * lambda);
    x[eb[1]] -= pr.separation * (wb1 * lambda);
  }
  return contacts;
}

}  // namespace tp::geometry::internal
