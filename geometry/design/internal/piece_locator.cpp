// geometry/design/internal/piece_locator.cpp: grid-based point location in a piece chart.
#include "geometry/design/internal/piece_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp::geometry::internal {
namespace {

// Barycentric weights this far below zero still count as inside (points on shared edges).
constexpr double kInsideTolerance = 1e-9;

}  // namespace

std::array<double, 3> barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const double det = cross(b - a, c - a);
  if (det == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  const double wb = cross(p - a, c - a) / det;
  const double wc = cross(b - a, p - a) / det;
  return {1 - wb - wc, wb, wc};
}

std::array<double, 3> closest_barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const auto w = barycentric(p, a, b, c);
  if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0) return w;
  // Outside: the nearest point lies on one of the three edges.
  const Vec2 v[3] = {a, b, c};
  double best = std::numeric_limits<double>::infinity();
  std::array<double, 3> out{1, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const Vec2 s = v[i], e = v[(i + 1) % 3];
    const Vec2 d = e - s;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(p - s, d) / len2, 0.0, 1.0) : 0.0;
    const Vec2 q = s + d * t;
    const double dist = norm(p - q);
    if (dist < best) {
      best = dist;
      out = {0, 0, 0};
      out[static_cast<size_t>(i)] = 1 - t;
      out[static_cast<size_t>((i + 1) % 3)] = t;
    }
  }
  return out;
}

PieceLocator::PieceLocator(const PieceMesh& mesh) : mesh_(&mesh) {
  for (Vec2 v : mesh.vertices_mm) box_.add(v);
  if (box_.empty() || mesh.triangles.empty()) return;
  // About two triangles per cell keeps lookups short and memory linear in the mesh size.
  const double area = std::max(box_.width() * box_.height(), 1e-6);
  cell_mm_ = std::max(std::sqrt(area / std::max<size_t>(1, mesh.triangles.size()) * 2.0), 1e-3);
  nx_ = std::max(1, static_cast<int>(std::ceil(box_.width() / cell_mm_)) + 1);
  ny_ = std::max(1, static_cast<int>(std::ceil(box_.height() / cell_mm_)) + 1);
  std::vector<int> counts(static_cast<size_t>(nx_) * ny_ + 1, 0);
  auto for_cells = [&](const std::array<int, 3>& t, auto&& fn) {
    Box2 b;
    for (int k = 0; k < 3; ++k) b.add(mesh.vertices_mm[static_cast<size_t>(t[static_cast<size_t>(k)])]);
    for (int y = cell_y(b.min.y); y <= cell_y(b.max.y); ++y)
      for (int x = cell_x(b.min.x); x <= cell_x(b.max.x); ++x) fn(y * nx_ + x);
  };
  for (const auto& t : mesh.triangles) for_cells(t, [&](int c) { ++counts[static_cast<size_t>(c) + 1]; });
  for (size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
  cell_start_ = counts;
  cell_tris_.resize(static_cast<size_t>(counts.back()));
  std::vector<int> fill(counts.begin(), counts.end() - 1);
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for_cells(mesh.triangles[i], [&](int c) { cell_tris_[static_cast<size_t>(fill[static_cast<size_t>(c)]++)] = static_cast<int>(i); });
}

int PieceLocator::cell_x(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - box_.min.x) / cell_mm_)), 0, nx_ - 1);
}
int PieceLocator::cell_y(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - box_.min.y) / cell_mm_)), 0, ny_ - 1);
}

ChartLocation PieceLocator::locate(Vec2 p) const {
  ChartLocation out;
  if (!mesh_ || nx_ == 0) return out;
  if (p.x < box_.min.x - cell_mm_ || p.x > box_.max.x + cell_mm_ || p.y < box_.min.y - cell_mm_ ||
      p.y > box_.max.y + cell_mm_)
    return out;
  const int c = cell_y(p.y) * nx_ + cell_x(p.x);
  double best = -std::numeric_limits<double>::infinity();
  for (int k = cell_start_[static_cast<size_t>(c)]; k < cell_start_[static_cast<size_t>(c) + 1]; ++k) {
    const int t = cell_tris_[static_cast<size_t>(k)];
    const auto& tri = mesh_->triangles[static_cast<size_t>(t)];
    const auto w = barycentric(p, mesh_->vertices_mm[static_cast<size_t>(tri[0])],
                               mesh_->vertices_mm[static_cast<size_t>(tri[1])],
                               mesh_->vertices_mm[static_cast<size_t>(tri[2])]);
    const double lo = std::min({w[0], w[1], w[2]});
    // Keep the most inside triangle so points on shared edges resolve deterministically.
    if (lo >= -kInsideTolerance && lo > best) {
      best = lo;
      out.triangle = t;
      out.bary = w;
    }
  }
  return out;
}

ChartLocation PieceLocator::nearest(Vec2 p) const {
  ChartLocation inside = locate(p);
  if (inside.triangle >= 0 || !mesh_ || nx_ == 0) return inside;
  // Search rings of cells around p's (clamped) cell until a ring cannot hold anything closer.
  const int cx = cell_x(p.x), cy = cell_y(p.y);
  double best = std::numeric_limits<double>::infinity();
  ChartLocation out;
  const int max_ring = std::max(nx_, ny_);
  for (int ring = 0; ring <= max_ring; ++ring) {
    for (int y = cy - ring; y <= cy + ring; ++y) {
      for (int x = cx - ring; x <= cx + ring; ++x) {
        if (x < 0 || y < 0 || x >= nx_ || y >= ny_) continue;
        if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
        const int c = y * nx_ + x;
        for (int k = cell_start_[static_cast<size_t>(c)]; k < cell_start_[static_cast<size_t>(c) + 1]; ++k) {
          const int t = cell_tris_[static_cast<size_t>(k)];
          const auto& tri = mesh_->triangles[static_cast<size_t>(t)];
          const Vec2 a = mesh_->vertices_mm[static_cast<size_t>(tri[0])];
          const Vec2 b = mesh_->vertices_mm[static_cast<size_t>(tri[1])];
          const Vec2 cc = mesh_->vertices_mm[static_cast<size_t>(tri[2])];
          const auto w = closest_barycentric(p, a, b, cc);
          const Vec2 q = a * w[0] + b * w[1] + cc * w[2];
          const double d = norm(p - q);
          if (d < best) {
            best = d;
            out.triangle = t;
            out.bary = w;
          }
        }
      }
    }
    // Cells of the next ring are at least `ring * cell` away from p's cell (p may lie outside the grid).
    const double ring_reach = ring * cell_mm_;
    const double outside = std::max({box_.min.x - p.x, p.x - box_.max.x, box_.min.y - p.y, p.y - box_.max.y, 0.0});
    if (out.triangle >= 0 && best <= ring_reach - outside) break;
  }
  return out;
}

}  // namespace tp::geometry::internal
