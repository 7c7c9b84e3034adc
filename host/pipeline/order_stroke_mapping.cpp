// host/pipeline/order_stroke_mapping.cpp: stroke points from the base garment to another size's
// through their pieces' pattern coordinates (closest point, mean value coordinates, chart lift).
#include "host/pipeline/order_stroke_mapping.h"

#include <array>
#include <cmath>
#include <limits>

namespace tp::host {

namespace {

using geometry::Vec2;
using geometry::Vec3;

/// Samples per pattern edge for the outline both sizes are compared on.
constexpr int kSamplesPerEdge = 24;
/// A graded position may lie this far outside the target mesh (its chords cut curved seams).
constexpr double kOutsideMeshMm = 3.0;

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5), as
// barycentric weights of a, b, c.
std::array<double, 3> closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

// The piece's seam-line outline, each edge resampled at the same fractions of its length.
std::vector<Vec2> resampled_outline(const geometry::Piece& piece) {
  std::vector<Vec2> out;
  for (const geometry::Edge& e : piece.edges) {
    std::vector<double> acc{0};
    for (size_t i = 1; i < e.points_mm.size(); ++i)
      acc.push_back(acc.back() + norm(e.points_mm[i] - e.points_mm[i - 1]));
    size_t seg = 1;
    for (int k = 0; k < kSamplesPerEdge; ++k) {
      const double s = acc.back() * k / kSamplesPerEdge;
      while (seg + 1 < acc.size() && acc[seg] < s) ++seg;
      const double len = acc[seg] - acc[seg - 1];
      const double t = len > 0 ? (s - acc[seg - 1]) / len : 0;
      out.push_back(e.points_mm[seg - 1] + (e.points_mm[seg] - e.points_mm[seg - 1]) * t);
    }
  }
  return out;
}

// Mean value coordinates of q over polygon v (Floater 2003; on an edge or vertex: linear there).
std::vector<double> mean_value_coordinates(const std::vector<Vec2>& v, Vec2 q) {
  const size_t n = v.size();
  std::vector<double> w(n, 0.0);
  std::vector<Vec2> d(n);
  std::vector<double> r(n);
  for (size_t i = 0; i < n; ++i) {
    d[i] = v[i] - q;
    r[i] = norm(d[i]);
    if (r[i] < 1e-9) {
      w[i] = 1;
      return w;
    }
  }
  std::vector<double> tan_half(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double c = cross(d[i], d[j]), dt = dot(d[i], d[j]);
    if (std::abs(c) < 1e-9 * r[i] * r[j] && dt < 0) {
      // q on edge (i, j): the two end points alone.
      std::fill(w.begin(), w.end(), 0.0);
      const double t = r[i] / (r[i] + r[j]);
      w[i] = 1 - t;
      w[j] = t;
      return w;
    }
    // tan(alpha / 2) = (1 - cos) / sin, from |d_i||d_j| (1 - cos) = r_i r_j - dot and sin ~ cross.
    tan_half[i] = (r[i] * r[j] - dt) / c;
  }
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    w[i] = (tan_half[(i + n - 1) % n] + tan_half[i]) / r[i];
    sum += w[i];
  }
  for (double& x : w) x /= sum;
  return w;
}

const geometry::GarmentPiece* chart_of(const geometry::Garment& g, int piece) {
  for (const auto& gp : g.pieces)
    if (gp.piece == piece) return &gp;
  return nullptr;
}

}  // namespace

std::optional<std::vector<MappedStrokePoint>> map_stroke_through_pieces(const std::vector<Vec3>& points_mm,
                                                                        const SizedGarment& base,
                                                                        const SizedGarment& target, std::string& why) {
  std::vector<MappedStrokePoint> out;
  for (const Vec3& p : points_mm) {
    // 1. The closest point of the base garment: its piece and pattern position.
    double best = std::numeric_limits<double>::infinity();
    const geometry::GarmentPiece* best_gp = nullptr;
    Vec2 q;
    Vec3 offset;
    for (const geometry::GarmentPiece& gp : base.garment->pieces) {
      for (const auto& t : gp.mesh.triangles) {
        const Vec3 a = base.garment->vertices_mm[static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(t[0])])];
        const Vec3 b = base.garment->vertices_mm[static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(t[1])])];
        const Vec3 c = base.garment->vertices_mm[static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(t[2])])];
        const auto w = closest_on_triangle(p, a, b, c);
        const Vec3 x = a * w[0] + b * w[1] + c * w[2];
        const double d = norm(p - x);
        if (d < best) {
          best = d;
          best_gp = &gp;
          offset = p - x;
          q = gp.mesh.vertices_mm[static_cast<size_t>(t[0])] * w[0] +
              gp.mesh.vertices_mm[static_cast<size_t>(t[1])] * w[1] +
              gp.mesh.vertices_mm[static_cast<size_t>(t[2])] * w[2];
        }
      }
    }
    if (!best_gp) {
      why = "the base garment has no triangles";
      return std::nullopt;
    }
    // 2. The same place relative to the seam line of the target's piece of the same name.
    const geometry::Piece& bp = base.pattern->pieces[static_cast<size_t>(best_gp->piece)];
    int tpi = -1;
    for (size_t k = 0; k < target.pattern->pieces.size(); ++k)
      if (target.pattern->pieces[k].name == bp.name) tpi = static_cast<int>(k);
    const geometry::GarmentPiece* tgp = tpi >= 0 ? chart_of(*target.garment, tpi) : nullptr;
    if (!tgp) {
      why = "piece '" + bp.name + "' has no namesake on the other size's garment";
      return std::nullopt;
    }
    const geometry::Piece& tp = target.pattern->pieces[static_cast<size_t>(tpi)];
    if (tp.edges.size() != bp.edges.size()) {
      why = "piece '" + bp.name + "' has " + std::to_string(bp.edges.size()) + " edges in one size and " +
            std::to_string(tp.edges.size()) + " in the other";
      return std::nullopt;
    }
    const auto lambda = mean_value_coordinates(resampled_outline(bp), q);
    const auto target_outline = resampled_outline(tp);
    Vec2 qt;
    for (size_t i = 0; i < lambda.size(); ++i) qt = qt + target_outline[i] * lambda[i];
    // 3. Lifted onto the target garment through its chart (the nearest triangle when a curved
    // seam line passes outside the mesh's chords).
    double best2 = std::numeric_limits<double>::infinity();
    Vec3 lifted;
    for (const auto& t : tgp->mesh.triangles) {
      const Vec2 a = tgp->mesh.vertices_mm[static_cast<size_t>(t[0])],
                 b = tgp->mesh.vertices_mm[static_cast<size_t>(t[1])],
                 c = tgp->mesh.vertices_mm[static_cast<size_t>(t[2])];
      const auto w = closest_on_triangle({qt.x, qt.y, 0}, {a.x, a.y, 0}, {b.x, b.y, 0}, {c.x, c.y, 0});
      const Vec2 x = a * w[0] + b * w[1] + c * w[2];
      const double d = norm(qt - x);
      if (d < best2) {
        best2 = d;
        const auto v3 = [&](int i) {
          return target.garment
              ->vertices_mm[static_cast<size_t>(tgp->vertex_3d[static_cast<size_t>(t[static_cast<size_t>(i)])])];
        };
        lifted = v3(0) * w[0] + v3(1) * w[1] + v3(2) * w[2];
      }
    }
    if (!(best2 <= kOutsideMeshMm)) {
      why = "piece '" + bp.name + "': the graded stroke point lies " + std::to_string(best2) +
            " mm outside the other size's piece";
      return std::nullopt;
    }
    out.push_back({bp.name, lifted + offset});
  }
  return out;
}

}  // namespace tp::host
