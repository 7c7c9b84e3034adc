// geometry/sewing/internal/arap_solver.cpp: ARAP local-global cloth relaxation with body contact.
#include "geometry/sewing/internal/arap_solver.h"

#include <Eigen/Sparse>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "geometry/common/thread_pool.h"
#include "geometry/common/tolerances.h"

namespace tp::geometry::internal {
namespace {

/// A deformation whose largest squared singular value is below this has collapsed to a point.
constexpr double kZeroStretch = 1e-20;

// Vertices whose interpolated distance exceeds the clearance by this many grid steps are free.
constexpr double kCullCells = 0.4;

// Runs fn(begin, end, slot) over [0, n) split into one range per pool thread (slot = range
// index), the same ranges whichever worker runs them.
template <class Fn>
void parallel_for(int n, ThreadPool& pool, Fn&& fn) {
  const int ranges = pool.size();
  if (ranges == 1 || n < 256) {
    fn(0, n, 0);
    return;
  }
  pool.parallel_for(ranges, [&](int t, int) {
    fn(static_cast<int>(static_cast<long>(n) * t / ranges), static_cast<int>(static_cast<long>(n) * (t + 1) / ranges),
       t);
  });
}

int push_out(std::vector<Vec3>& x, const BodySdf& body, double clearance_mm, ThreadPool& pool,
             const std::vector<Vec3>* fallback);

// Per-triangle constants: area and G (3x2) with F = [x0 x1 x2] G.
struct TriConst {
  double area = 0;
  double g[3][2] = {};
};

TriConst triangle_constants(const std::array<Vec2, 3>& r) {
  TriConst c;
  Vec2 e1 = r[1] - r[0], e2 = r[2] - r[0];
  double det = cross(e1, e2);
  c.area = 0.5 * std::abs(det);
  if (std::abs(det) < kParallelDeterminant) return c;
  // Dm = [e1 e2]; Dm^-1 rows.
  double inv[2][2] = {{e2.y / det, -e2.x / det}, {-e1.y / det, e1.x / det}};
  for (int j = 0; j < 2; ++j) {
    c.g[1][j] = inv[0][j];
    c.g[2][j] = inv[1][j];
    c.g[0][j] = -inv[0][j] - inv[1][j];
  }
  return c;
}

// Closest 3x2 matrix with orthonormal columns to F (columns f0, f1): F (F^T F)^{-1/2}.
void closest_rotation(Vec3 f0, Vec3 f1, Vec3& r0, Vec3& r1) {
  double a = dot(f0, f0), b = dot(f0, f1), d = dot(f1, f1);
  // Eigen-decomposition of the symmetric 2x2 [a b; b d].
  double tr = a + d, det = a * d - b * b;
  double disc = std::sqrt(std::max(tr * tr / 4 - det, 0.0));
  double l1 = tr / 2 + disc, l2 = std::max(tr / 2 - disc, 0.0);
  if (l1 < kZeroStretch) {
    r0 = {1, 0, 0};
    r1 = {0, 1, 0};
    return;
  }
  if (l2 < kParallelDeterminant * l1) {
    // Degenerate (collapsed) triangle: keep the dominant direction, pick any orthogonal one.
    r0 = normalized(f0 + f1 * 0.0);
    if (norm(r0) == 0) r0 = {1, 0, 0};
    Vec3 o = std::abs(r0.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    r1 = normalized(cross(cross(r0, o), r0));
    return;
  }
  Vec2 v1 = std::abs(b) > 1e-30 ? normalized(Vec2{b, l1 - a}) : (a >= d ? Vec2{1, 0} : Vec2{0, 1});
  Vec2 v2 = perp(v1);
  double s1 = 1 / std::sqrt(l1), s2 = 1 / std::sqrt(l2);
  // (F^T F)^{-1/2} = s1 v1 v1^T + s2 v2 v2^T.
  double m00 = s1 * v1.x * v1.x + s2 * v2.x * v2.x;
  double m01 = s1 * v1.x * v1.y + s2 * v2.x * v2.y;
  double m11 = s1 * v1.y * v1.y + s2 * v2.y * v2.y;
  r0 = f0 * m00 + f1 * m01;
  r1 = f0 * m01 + f1 * m11;
}

}  // namespace

int push_out_of_body(std::vector<Vec3>& x, const BodySdf& body, double clearance_mm, int threads,
                      const std::vector<Vec3>* fallback) {
  ThreadPool pool(std::clamp(threads, 1, 8));
  return push_out(x, body, clearance_mm, pool, fallback);
}

namespace {

int push_out(std::vector<Vec3>& x, const BodySdf& body, double clearance_mm, ThreadPool& pool,
             const std::vector<Vec3>* fallback) {
  std::atomic<int> moved{0};
  parallel_for(static_cast<int>(x.size()), pool, [&](int b, int e, int) {
    int count = 0;
    for (int i = b; i < e; ++i) {
      // The interpolated grid is within a cell of the truth: skip clearly free vertices.
      if (body.approx_distance_mm(x[i]) > clearance_mm + kCullCells * body.spacing_mm()) continue;
      BodySdf::Hit h = body.query(x[i]);
      if (!h.near && h.distance_mm < 0 && fallback) {
        // Deeper than the band: no surface to push to, so the vertex keeps its last position.
        x[i] = (*fallback)[i];
        ++count;
        continue;
      }
      if (h.distance_mm >= clearance_mm || !h.near) continue;
      x[i] = h.closest_mm + h.normal * clearance_mm;
      ++count;
    }
    moved += count;
  });
  return moved.load();
}

}  // namespace

Result<ClothStats> relax_cloth(ClothMesh& cloth, const BodySdf& body, const ClothParams& p, const CancelToken* cancel) {
  const int n = static_cast<int>(cloth.x_mm.size());
  const int nf = static_cast<int>(cloth.triangles.size());
  ClothStats stats;
  if (n == 0 || nf == 0) return stats;

  // Constants: triangle areas and gradients, vertex areas, mean edge length.
  std::vector<TriConst> tc(nf);
  std::vector<double> mass(n, 0.0);
  double edge_sum = 0;
  for (int f = 0; f < nf; ++f) {
    tc[f] = triangle_constants(cloth.rest_mm[f]);
    for (int k = 0; k < 3; ++k) {
      mass[cloth.triangles[f][k]] += tc[f].area / 3;
      edge_sum += norm(cloth.rest_mm[f][(k + 1) % 3] - cloth.rest_mm[f][k]);
    }
  }
  const double h = edge_sum / (3.0 * nf);
  std::vector<double> w(n);
  for (int i = 0; i < n; ++i) w[i] = p.proximal_weight * std::max(mass[i], 1e-6 * h * h) / (h * h);

  // System matrix: membrane Laplacian + seam springs + proximal diagonal; factorised once.
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<size_t>(nf) * 9 + cloth.springs.size() * 4 + n);
  for (int f = 0; f < nf; ++f) {
    const auto& t = cloth.triangles[f];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        trip.emplace_back(t[a], t[b], tc[f].area * (tc[f].g[a][0] * tc[f].g[b][0] + tc[f].g[a][1] * tc[f].g[b][1]));
  }
  for (const auto& s : cloth.springs) {
    trip.emplace_back(s[0], s[0], p.spring_weight);
    trip.emplace_back(s[1], s[1], p.spring_weight);
    trip.emplace_back(s[0], s[1], -p.spring_weight);
    trip.emplace_back(s[1], s[0], -p.spring_weight);
  }
  const bool use_edges = p.edge_weight > 0 && !cloth.edges.empty() && cloth.edge_rest_mm.size() == cloth.edges.size();
  if (use_edges)
    for (const auto& e : cloth.edges) {
      trip.emplace_back(e[0], e[0], p.edge_weight);
      trip.emplace_back(e[1], e[1], p.edge_weight);
      trip.emplace_back(e[0], e[1], -p.edge_weight);
      trip.emplace_back(e[1], e[0], -p.edge_weight);
    }
  for (int i = 0; i < n; ++i) trip.emplace_back(i, i, w[i]);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  solver.compute(K);
  if (solver.info() != Eigen::Success) return fail(ErrorCode::kSewing, "cloth system could not be factorised");

  const int threads = std::clamp(p.threads, 1, 8);
  ThreadPool pool(threads);
  std::vector<Eigen::MatrixXd> rhs_part(threads, Eigen::MatrixXd::Zero(n, 3));
  std::vector<double> energy_part(threads, 0.0);
  Eigen::MatrixXd rhs(n, 3), sol(n, 3);
  std::vector<Vec3>& x = cloth.x_mm;

  // Local step at x: best rotation per triangle into per-thread right-hand sides; returns the
  // membrane energy sum_t A_t |F_t - R_t|^2.
  const auto local_step = [&]() {
    parallel_for(nf, pool, [&](int b, int e, int slot) {
      Eigen::MatrixXd& r = rhs_part[slot];
      r.setZero();
      double energy = 0;
      for (int f = b; f < e; ++f) {
        const auto& t = cloth.triangles[f];
        const TriConst& c = tc[f];
        if (c.area == 0) continue;
        Vec3 f0{}, f1{};
        for (int k = 0; k < 3; ++k) {
          f0 += x[t[k]] * c.g[k][0];
          f1 += x[t[k]] * c.g[k][1];
        }
        Vec3 r0, r1;
        closest_rotation(f0, f1, r0, r1);
        energy += c.area * (dot(f0 - r0, f0 - r0) + dot(f1 - r1, f1 - r1));
        for (int k = 0; k < 3; ++k) {
          Vec3 v = (r0 * c.g[k][0] + r1 * c.g[k][1]) * c.area;
          r(t[k], 0) += v.x;
          r(t[k], 1) += v.y;
          r(t[k], 2) += v.z;
        }
      }
      energy_part[slot] = energy;
    });
    double e = 0;
    for (int t = 0; t < threads; ++t) e += energy_part[t];
    // Rest-length edges: each projected onto its rest length along its current direction.
    if (use_edges) {
      Eigen::MatrixXd& r = rhs_part[0];
      for (size_t k = 0; k < cloth.edges.size(); ++k) {
        const int i = cloth.edges[k][0], j = cloth.edges[k][1];
        const Vec3 d = x[i] - x[j];
        const double len = norm(d);
        const Vec3 proj = len > 0 ? d * (cloth.edge_rest_mm[k] / len) : d;
        e += p.edge_weight * dot(d - proj, d - proj);
        const Vec3 v = proj * p.edge_weight;
        r(i, 0) += v.x, r(i, 1) += v.y, r(i, 2) += v.z;
        r(j, 0) -= v.x, r(j, 1) -= v.y, r(j, 2) -= v.z;
      }
    }
    return e;
  };

  // Anderson acceleration of the fixed-point map x -> G(x) (local, global, contact), with
  // an energy safeguard: an extrapolated iterate that raises the energy is replaced by the
  // plain one (Peng et al. 2018, "Anderson acceleration for geometry optimization").
  const int window = p.anderson_window;
  std::vector<Eigen::VectorXd> d_g, d_f;  // history of differences of G(x) and of G(x) - x
  Eigen::VectorXd g_prev, f_prev, g_vec(3 * n), f_vec(3 * n);
  std::vector<Vec3> plain;  // last plain iterate G(x), always pushed out of the body
  std::vector<Vec3> last_plain;
  double accepted_energy = std::numeric_limits<double>::infinity();

  for (int it = 0; it < p.iterations; ++it) {
    if (cancel && cancel->cancelled()) return fail(ErrorCode::kCancelled, "sewing cancelled");
    if (p.on_iteration) p.on_iteration();
    double energy = local_step();
    if (window > 0 && !plain.empty() && energy > accepted_energy) {
      x = plain;
      d_g.clear(), d_f.clear();
      energy = local_step();
    }
    accepted_energy = energy;
    rhs.setZero();
    for (const auto& r : rhs_part) rhs += r;
    for (int i = 0; i < n; ++i) {
      rhs(i, 0) += w[i] * x[i].x;
      rhs(i, 1) += w[i] * x[i].y - mass[i] * p.gravity_per_mm;
      rhs(i, 2) += w[i] * x[i].z;
    }
    // Global step: the three coordinates are independent solves with one factorisation.
    pool.parallel_for(3, [&](int c, int) { sol.col(c) = solver.solve(rhs.col(c)); });

    last_plain = plain.empty() ? x : plain;
    plain.resize(n);
    for (int i = 0; i < n; ++i) plain[i] = Vec3{sol(i, 0), sol(i, 1), sol(i, 2)};
    // Contact: nothing stays inside the body or closer than the clearance.
    stats.contacts = push_out(plain, body, p.clearance_mm, pool, &last_plain);
    double move = 0;
    for (int i = 0; i < n; ++i) {
      move = std::max(move, norm(plain[i] - x[i]));
      g_vec.segment<3>(3 * i) << plain[i].x, plain[i].y, plain[i].z;
      f_vec.segment<3>(3 * i) << plain[i].x - x[i].x, plain[i].y - x[i].y, plain[i].z - x[i].z;
    }
    stats.iterations = it + 1;
    stats.last_move_mm = move;
    if (!std::isfinite(move)) return fail(ErrorCode::kSewing, "cloth relaxation diverged");
    if (move < p.tolerance_mm || window <= 0) {
      x = plain;
      if (move < p.tolerance_mm) break;
      continue;
    }
    if (g_prev.size() == g_vec.size()) {
      d_g.push_back(g_vec - g_prev);
      d_f.push_back(f_vec - f_prev);
      if (static_cast<int>(d_g.size()) > window) d_g.erase(d_g.begin()), d_f.erase(d_f.begin());
    }
    g_prev = g_vec, f_prev = f_vec;
    Eigen::VectorXd next = g_vec;
    if (!d_f.empty()) {
      const int m = static_cast<int>(d_f.size());
      Eigen::MatrixXd a(m, m);
      Eigen::VectorXd rhs_aa(m);
      for (int i = 0; i < m; ++i) {
        rhs_aa(i) = d_f[i].dot(f_vec);
        for (int j = 0; j < m; ++j) a(i, j) = d_f[i].dot(d_f[j]);
      }
      a.diagonal().array() += 1e-10 * (a.trace() + 1e-30);
      Eigen::VectorXd theta = a.ldlt().solve(rhs_aa);
      for (int i = 0; i < m; ++i) next -= theta(i) * d_g[i];
    }
    for (int i = 0; i < n; ++i) x[i] = Vec3{next(3 * i), next(3 * i + 1), next(3 * i + 2)};
  }
  // End on a plain, pushed-out iterate.
  if (!plain.empty()) x = plain;
  return stats;
}

}  // namespace tp::geometry::internal
