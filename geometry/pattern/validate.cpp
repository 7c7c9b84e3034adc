// geometry/pattern/validate.cpp: pattern checks with messages naming piece, edge and stitch.
#include "geometry/pattern/validate.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/pattern/internal/segment_intersection.h"
#include "geometry/pattern/internal/text.h"

namespace tp::geometry {
namespace {

using internal::mm;
using internal::point;

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

std::string piece_label(const Piece& p, size_t index) {
  return p.name.empty() ? "piece #" + std::to_string(index) : "piece '" + p.name + "'";
}

std::string edge_label(const Piece& p, int e) {
  if (e < 0 || e >= static_cast<int>(p.edges.size())) return "edge #" + std::to_string(e);
  return p.edges[e].name.empty() ? "edge #" + std::to_string(e) : "edge '" + p.edges[e].name + "'";
}

void check_outline(const Piece& piece, const std::string& who, const ValidationOptions& o,
                   std::vector<Error>& out) {
  auto problem = [&](ErrorCode c, const std::string& m) { out.push_back(Error{c, who + ": " + m}); };
  const int n = static_cast<int>(piece.edges.size());
  if (n == 0) {
    problem(ErrorCode::kInvalidPattern, "has no edges");
    return;
  }
  bool geometry_ok = true;
  std::set<std::string> names;
  for (int i = 0; i < n; ++i) {
    const Edge& e = piece.edges[i];
    if (e.name.empty()) problem(ErrorCode::kInvalidPattern, "edge #" + std::to_string(i) + " has no name");
    else if (!names.insert(e.name).second)
      problem(ErrorCode::kInvalidPattern, "duplicate edge name '" + e.name + "'");
    if (e.points_mm.size() < 2) {
      problem(ErrorCode::kInvalidPattern, edge_label(piece, i) + " has fewer than 2 points");
      geometry_ok = false;
      continue;
    }
    if (!std::all_of(e.points_mm.begin(), e.points_mm.end(), finite)) {
      problem(ErrorCode::kInvalidPattern, edge_label(piece, i) + " has a non-finite coordinate");
      geometry_ok = false;
      continue;
    }
    double len = edge_length_mm(e);
    if (len < o.min_edge_length_mm)
      problem(ErrorCode::kInvalidPattern, edge_label(piece, i) + " has zero length (" + mm(len) + " mm)");
  }
  if (!geometry_ok) return;
  // Consecutive edges must meet: the outline is closed.
  for (int i = 0; i < n; ++i) {
    const Edge& a = piece.edges[i];
    const Edge& b = piece.edges[(i + 1) % n];
    double gap = norm(b.points_mm.front() - a.points_mm.back());
    if (gap > o.join_tolerance_mm) {
      problem(ErrorCode::kInvalidPattern, "outline is open: " + edge_label(piece, i) + " ends at " +
                                              point(a.points_mm.back()) + " but " +
                                              edge_label(piece, (i + 1) % n) + " starts at " +
                                              point(b.points_mm.front()) + " (gap " + mm(gap) + " mm)");
      geometry_ok = false;
    }
  }
  if (!geometry_ok) return;
  // Vertices of the outline with the edge each following segment belongs to.
  std::vector<Vec2> poly;
  std::vector<int> owner;
  for (int i = 0; i < n; ++i) {
    const auto& pts = piece.edges[i].points_mm;
    for (size_t k = 0; k + 1 < pts.size(); ++k) {
      if (!poly.empty() && norm(pts[k] - poly.back()) <= 0) continue;
      poly.push_back(pts[k]);
      owner.push_back(i);
    }
  }
  while (poly.size() > 1 && norm(poly.front() - poly.back()) <= 0) {
    poly.pop_back();
    owner.pop_back();
  }
  if (poly.size() < 3) {
    problem(ErrorCode::kInvalidPattern, "outline has fewer than 3 distinct vertices");
    return;
  }
  if (auto hit = internal::find_self_intersection(poly)) {
    problem(ErrorCode::kInvalidPattern, "outline intersects itself: " + edge_label(piece, owner[hit->segment_a]) +
                                            " meets " + edge_label(piece, owner[hit->segment_b]) + " near " +
                                            point(hit->where));
    return;
  }
  double area = signed_area(poly);
  if (area <= 0 && o.require_counter_clockwise)
    problem(ErrorCode::kInvalidPattern, area == 0 ? "outline encloses no area"
                                                  : "outline is clockwise (area " + mm(area) + " mm²); "
                                                    "reverse it (orient_counter_clockwise)");
}

void check_features(const Piece& piece, const std::string& who, std::vector<Error>& out) {
  auto problem = [&](ErrorCode c, const std::string& m) { out.push_back(Error{c, who + ": " + m}); };
  const int n = static_cast<int>(piece.edges.size());
  auto edge_ok = [&](int e) { return e >= 0 && e < n; };
  for (size_t k = 0; k < piece.notches.size(); ++k) {
    const Notch& nt = piece.notches[k];
    std::string nl = "notch " + (nt.name.empty() ? "#" + std::to_string(k) : "'" + nt.name + "'");
    if (!edge_ok(nt.edge)) {
      problem(ErrorCode::kUnknownReference, nl + " is on " + edge_label(piece, nt.edge) + ", which does not exist");
      continue;
    }
    double len = edge_length_mm(piece.edges[nt.edge]);
    if (!(nt.position_mm >= 0 && nt.position_mm <= len + 1e-6))
      problem(ErrorCode::kInvalidPattern, nl + " at " + mm(nt.position_mm) + " mm lies off " +
                                              edge_label(piece, nt.edge) + " (length " + mm(len) + " mm)");
  }
  for (const Dart& d : piece.darts) {
    if (!edge_ok(d.leg_a) || !edge_ok(d.leg_b))
      problem(ErrorCode::kUnknownReference, "dart '" + d.name + "' names a leg edge that does not exist");
    else if (d.leg_a == d.leg_b)
      problem(ErrorCode::kInvalidPattern, "dart '" + d.name + "' has the same edge as both legs");
  }
  if (piece.fold_edge && !edge_ok(*piece.fold_edge))
    problem(ErrorCode::kUnknownReference, "fold edge #" + std::to_string(*piece.fold_edge) + " does not exist");
  if (piece.grain && (!finite(piece.grain->from_mm) || !finite(piece.grain->to_mm) ||
                      norm(piece.grain->to_mm - piece.grain->from_mm) <= 0))
    problem(ErrorCode::kInvalidPattern, "grain line has no direction");
}

// How far two stitched spans may differ in length: the larger of the absolute and relative
// tolerances, the latter of the longer span.
double allowed_difference_mm(const ValidationOptions& o, double longer_mm) {
  return std::max(o.stitch_length_tolerance_mm, o.stitch_length_tolerance_ratio * longer_mm);
}

void check_stitches(const Pattern& pattern, const ValidationOptions& o, std::vector<Error>& out) {
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    const Stitch& st = pattern.stitches[s];
    std::string who = "stitch #" + std::to_string(s);
    bool refs_ok = true;
    for (const EdgeSpan* sp : {&st.a, &st.b}) {
      if (sp->piece < 0 || sp->piece >= static_cast<int>(pattern.pieces.size())) {
        out.push_back(Error{ErrorCode::kUnknownReference, who + ": piece #" + std::to_string(sp->piece) + " does not exist"});
        refs_ok = false;
        continue;
      }
      const Piece& p = pattern.pieces[sp->piece];
      if (sp->edge < 0 || sp->edge >= static_cast<int>(p.edges.size())) {
        out.push_back(Error{ErrorCode::kUnknownReference,
                            who + ": piece '" + p.name + "' has no edge #" + std::to_string(sp->edge)});
        refs_ok = false;
        continue;
      }
      double len = edge_length_mm(p.edges[sp->edge]);
      auto r = span_range_mm(pattern, *sp);
      if (!(r[0] >= -o.span_range_tolerance_mm && r[1] <= len + o.span_range_tolerance_mm && r[0] < r[1])) {
        out.push_back(Error{ErrorCode::kInvalidPattern, who + ": span [" + mm(r[0]) + ", " + mm(r[1]) + "] mm of " +
                                                            describe_edge(pattern, sp->piece, sp->edge) +
                                                            " is out of range (edge length " + mm(len) + " mm)"});
        refs_ok = false;
      }
    }
    if (!refs_ok) continue;
    double la = span_length_mm(pattern, st.a), lb = span_length_mm(pattern, st.b);
    const double allowed = allowed_difference_mm(o, std::max(la, lb));
    if (st.ease_ratio > 0) {
      // Marked eased or gathered: the longer side may be up to ease_ratio times the shorter.
      const double longer = std::max(la, lb), shorter = std::min(la, lb);
      if (longer > st.ease_ratio * shorter + allowed)
        out.push_back(Error{ErrorCode::kInvalidPattern,
                            who + ": " + describe_edge(pattern, st.a.piece, st.a.edge) + " is " + mm(la) + " mm and " +
                                describe_edge(pattern, st.b.piece, st.b.edge) + " is " + mm(lb) +
                                " mm: more than the stitch's ease ratio " + mm(st.ease_ratio) + " allows"});
      continue;
    }
    if (std::abs(la - lb) > allowed)
      out.push_back(Error{ErrorCode::kInvalidPattern,
                          who + ": " + describe_edge(pattern, st.a.piece, st.a.edge) + " is " + mm(la) + " mm but " +
                              describe_edge(pattern, st.b.piece, st.b.edge) + " is " + mm(lb) +
                              " mm (difference " + mm(std::abs(la - lb)) + " mm, allowed " + mm(allowed) + " mm)"});
  }
}

}  // namespace

double mismatch_ease_ratio(const Pattern& pattern, const Stitch& stitch, const ValidationOptions& options) {
  const double la = span_length_mm(pattern, stitch.a), lb = span_length_mm(pattern, stitch.b);
  const double longer = std::max(la, lb), shorter = std::min(la, lb);
  return shorter > 0 && longer - shorter > allowed_difference_mm(options, longer) ? longer / shorter : 0;
}

std::vector<Error> find_pattern_problems(const Pattern& pattern, const ValidationOptions& options) {
  std::vector<Error> out;
  if (pattern.pieces.empty()) out.push_back(Error{ErrorCode::kInvalidPattern, "pattern has no pieces"});
  std::set<std::string> names;
  for (size_t i = 0; i < pattern.pieces.size(); ++i) {
    const Piece& p = pattern.pieces[i];
    std::string who = piece_label(p, i);
    if (p.name.empty()) out.push_back(Error{ErrorCode::kInvalidPattern, who + " has no name"});
    else if (!names.insert(p.name).second)
      out.push_back(Error{ErrorCode::kInvalidPattern, "duplicate piece name '" + p.name + "'"});
    check_outline(p, who, options, out);
    check_features(p, who, out);
  }
  check_stitches(pattern, options, out);
  return out;
}

Status validate_pattern(const Pattern& pattern, const ValidationOptions& options) {
  std::vector<Error> problems = find_pattern_problems(pattern, options);
  if (problems.empty()) return {};
  Error first = problems.front();
  if (problems.size() > 1) first.message += " (and " + std::to_string(problems.size() - 1) + " more problems)";
  return std::unexpected(first);
}

}  // namespace tp::geometry
