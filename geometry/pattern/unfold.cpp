// geometry/pattern/unfold.cpp: mirroring a half piece across its fold edge into the whole piece.
#include "geometry/pattern/unfold.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/pattern/curve.h"
#include "geometry/pattern/internal/text.h"

namespace tp::geometry {
namespace {

/// Points within this distance (mm) of the fold line lie on the fold.
constexpr double kOnFoldTolerance_mm = 0.05;
/// Notches within this distance (mm) of a fold edge's end sit at that end.
constexpr double kFoldEndTolerance_mm = 0.5;

/// Reflection across the line through p and q.
Affine2 reflection(Vec2 p, Vec2 q) {
  Vec2 d = normalized(q - p);
  double c = d.x * d.x - d.y * d.y, s = 2 * d.x * d.y;
  Affine2 r{c, s, 0, s, -c, 0};
  Vec2 off = p - r.apply(p);
  r.c = off.x;
  r.f = off.y;
  return r;
}

double distance_to_line(Vec2 x, Vec2 p, Vec2 q) { return std::abs(cross(normalized(q - p), x - p)); }

std::string unique_name(std::string base, std::set<std::string>& used) {
  std::string name = base;
  for (int k = 2; !used.insert(name).second; ++k) name = base + "_" + std::to_string(k);
  return name;
}

}  // namespace

Result<Piece> unfold_piece(const Piece& half, int fold_edge) {
  const int n = static_cast<int>(half.edges.size());
  std::string who = "piece '" + half.name + "'";
  if (fold_edge < 0 || fold_edge >= n)
    return fail(ErrorCode::kInvalidPattern, who + ": fold edge #" + std::to_string(fold_edge) + " does not exist");
  if (n < 3)
    return fail(ErrorCode::kInvalidPattern, who + ": a cut-on-fold piece needs at least 2 edges besides the fold");
  const Edge& fe = half.edges[fold_edge];
  if (fe.points_mm.size() < 2) return fail(ErrorCode::kInvalidPattern, who + ": fold edge has no points");
  const Vec2 p = fe.points_mm.front(), q = fe.points_mm.back();
  if (!(norm(q - p) > 0))
    return fail(ErrorCode::kInvalidPattern, who + ": fold edge '" + fe.name + "' has zero length");
  for (Vec2 x : fe.points_mm)
    if (distance_to_line(x, p, q) > kFoldStraightnessTolerance_mm)
      return fail(ErrorCode::kInvalidPattern, who + ": fold edge '" + fe.name + "' is not straight (a point is " +
                                                  internal::mm(distance_to_line(x, p, q)) + " mm off its line)");
  const Affine2 refl = reflection(p, q);

  // The half outline from the fold's end q round to its start p, and its mirror image from p to q.
  const int k = n - 1;
  std::vector<int> chain(k);
  for (int i = 0; i < k; ++i) chain[i] = (fold_edge + 1 + i) % n;
  std::vector<Edge> c(k), m(k);
  std::vector<double> len(k);
  std::set<std::string> used;
  for (int i = 0; i < k; ++i) {
    c[i] = half.edges[chain[i]];
    used.insert(c[i].name);
    len[i] = edge_length_mm(c[i]);
  }
  for (int i = 0; i < k; ++i) {
    m[i] = reversed_edge(transformed_edge(c[i], refl));
    m[i].name = unique_name(c[i].name + "_mirror", used);
  }

  // Whole outline: [m0 + c0], c1 .. c(k-2), [c(k-1) + m(k-1)], m(k-2) .. m1. Each source edge maps
  // to (new edge index, offset of its start along it, reversed?).
  struct Slot { int edge; double offset; bool reversed; };
  std::vector<Slot> c_slot(k), m_slot(k);
  Piece whole = half;
  whole.edges.clear();
  whole.notches.clear();
  whole.darts.clear();
  whole.internal_lines.clear();
  whole.drill_holes.clear();
  whole.fold_edge.reset();
  whole.fold_line_mm = std::array<Vec2, 2>{p, q};
  double mlen0 = edge_length_mm(m[0]);
  whole.edges.push_back(joined_edges(m[0], c[0]));
  whole.edges.back().name = c[0].name;
  m_slot[0] = {0, 0, true};
  c_slot[0] = {0, mlen0, false};
  for (int i = 1; i + 1 < k; ++i) {
    c_slot[i] = {static_cast<int>(whole.edges.size()), 0, false};
    whole.edges.push_back(c[i]);
  }
  const int joint_p = static_cast<int>(whole.edges.size());
  if (k >= 2) {
    c_slot[k - 1] = {joint_p, 0, false};
    m_slot[k - 1] = {joint_p, len[k - 1], true};
    whole.edges.push_back(joined_edges(c[k - 1], m[k - 1]));
    for (int i = k - 2; i >= 1; --i) {
      m_slot[i] = {static_cast<int>(whole.edges.size()), 0, true};
      whole.edges.push_back(m[i]);
    }
  }

  // Notches of the half and their mirror images.
  for (const Notch& nt : half.notches) {
    if (nt.edge == fold_edge) {
      double flen = edge_length_mm(fe);
      if (nt.position_mm <= kFoldEndTolerance_mm)
        whole.notches.push_back(Notch{nt.name, joint_p, len[k - 1], nt.type});
      else if (nt.position_mm >= flen - kFoldEndTolerance_mm)
        whole.notches.push_back(Notch{nt.name, 0, mlen0, nt.type});
      else
        whole.drill_holes.push_back(DrillHole{point_along_edge(fe, nt.position_mm), 0});
      continue;
    }
    int i = (nt.edge - fold_edge - 1 + n) % n;
    if (nt.edge < 0 || nt.edge >= n || i >= k) continue;
    const Slot& cs = c_slot[i];
    whole.notches.push_back(Notch{nt.name, cs.edge, cs.offset + nt.position_mm, nt.type});
    const Slot& ms = m_slot[i];
    whole.notches.push_back(Notch{nt.name.empty() ? "" : nt.name + "_mirror", ms.edge,
                                  ms.offset + (len[i] - nt.position_mm), nt.type});
  }
  // Darts lie on single edges of the chain; their mirror images use the mirrored edges.
  auto slot_of = [&](int edge, bool mirror) -> int {
    int i = (edge - fold_edge - 1 + n) % n;
    if (edge < 0 || edge >= n || i >= k) return -1;
    return mirror ? m_slot[i].edge : c_slot[i].edge;
  };
  for (const Dart& d : half.darts) {
    whole.darts.push_back(Dart{d.name, slot_of(d.leg_a, false), slot_of(d.leg_b, false)});
    whole.darts.push_back(Dart{d.name + "_mirror", slot_of(d.leg_b, true), slot_of(d.leg_a, true)});
  }
  for (const InternalLine& l : half.internal_lines) {
    whole.internal_lines.push_back(l);
    bool on_fold = std::all_of(l.points_mm.begin(), l.points_mm.end(),
                               [&](Vec2 x) { return distance_to_line(x, p, q) <= kOnFoldTolerance_mm; });
    if (on_fold) continue;
    InternalLine ml{l.name + "_mirror", l.points_mm};
    for (Vec2& x : ml.points_mm) x = refl.apply(x);
    whole.internal_lines.push_back(std::move(ml));
  }
  for (const DrillHole& h : half.drill_holes) {
    whole.drill_holes.push_back(h);
    if (distance_to_line(h.position_mm, p, q) > kOnFoldTolerance_mm)
      whole.drill_holes.push_back(DrillHole{refl.apply(h.position_mm), h.diameter_mm});
  }
  return whole;
}

}  // namespace tp::geometry
