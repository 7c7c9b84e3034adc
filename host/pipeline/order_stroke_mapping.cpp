// host/pipeline/order_stroke_mapping.cpp: stroke points from the base garment to another size's
// through their pieces' pattern coordinates (closest point, mean value coordinates, chart lift).
#include "host/pipeline/order_stroke_mapping.h"

#include <algorithm>
#include <cmath>

#include "geometry/common/tolerances.h"
#include "geometry/design/transfer_surface_points.h"

namespace tp::host {

namespace {

using geometry::Vec2;
using geometry::Vec3;

/// Samples per pattern edge for the outline both sizes are compared on.
constexpr int kSamplesPerEdge = 24;
/// A graded position may lie this far outside the target mesh (its chords cut curved seams).
constexpr double kOutsideMeshMm = 3.0;

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
    if (r[i] < geometry::kSamePoint_mm) {
      w[i] = 1;
      return w;
    }
  }
  std::vector<double> tan_half(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double c = cross(d[i], d[j]), dt = dot(d[i], d[j]);
    if (std::abs(c) < geometry::kBoundarySlack * r[i] * r[j] && dt < 0) {
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

}  // namespace

std::optional<std::vector<MappedStrokePoint>> map_stroke_through_pieces(const std::vector<Vec3>& points_mm,
                                                                        const SizedGarment& base,
                                                                        const SizedGarment& target, std::string& why) {
  // 1. The closest point of the base garment: its piece and pattern position.
  auto located = geometry::locate_on_pieces(*base.pattern, *base.garment, points_mm);
  if (!located) {
    why = located.error().message;
    return std::nullopt;
  }
  // 2. The same place relative to the seam line of the target's piece of the same name.
  std::vector<geometry::PiecePoint> graded;
  graded.reserve(located->size());
  for (const geometry::PiecePoint& at : *located) {
    const geometry::Piece& bp = base.pattern->pieces[static_cast<size_t>(at.piece)];
    int tpi = -1;
    for (size_t k = 0; k < target.pattern->pieces.size(); ++k)
      if (target.pattern->pieces[k].name == bp.name) tpi = static_cast<int>(k);
    const bool on_garment = tpi >= 0 && std::any_of(target.garment->pieces.begin(), target.garment->pieces.end(),
                                                    [&](const geometry::GarmentPiece& gp) { return gp.piece == tpi; });
    if (!on_garment) {
      why = "piece '" + bp.name + "' has no namesake on the other size's garment";
      return std::nullopt;
    }
    const geometry::Piece& tp = target.pattern->pieces[static_cast<size_t>(tpi)];
    if (tp.edges.size() != bp.edges.size()) {
      why = "piece '" + bp.name + "' has " + std::to_string(bp.edges.size()) + " edges in one size and " +
            std::to_string(tp.edges.size()) + " in the other";
      return std::nullopt;
    }
    const auto lambda = mean_value_coordinates(resampled_outline(bp), at.position_mm);
    const auto target_outline = resampled_outline(tp);
    Vec2 qt;
    for (size_t i = 0; i < lambda.size(); ++i) qt = qt + target_outline[i] * lambda[i];
    graded.push_back({tpi, qt, at.offset_mm});
  }
  // 3. Lifted onto the target garment through its chart (the nearest point of the piece when a
  // curved seam line passes outside the mesh's chords).
  auto placed = geometry::place_on_garment(*target.pattern, *target.garment, graded);
  if (!placed) {
    why = placed.error().message;
    return std::nullopt;
  }
  std::vector<MappedStrokePoint> out;
  out.reserve(graded.size());
  for (size_t i = 0; i < graded.size(); ++i) {
    const std::string& name = target.pattern->pieces[static_cast<size_t>(graded[i].piece)].name;
    if (!((*placed)[i].outside_mm <= kOutsideMeshMm)) {
      why = "piece '" + name + "': the graded stroke point lies " + std::to_string((*placed)[i].outside_mm) +
            " mm outside the other size's piece";
      return std::nullopt;
    }
    out.push_back({name, (*placed)[i].position_mm + graded[i].offset_mm});
  }
  return out;
}

}  // namespace tp::host
