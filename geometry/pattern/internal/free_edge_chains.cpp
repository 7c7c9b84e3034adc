// geometry/pattern/internal/free_edge_chains.cpp: walking round the seam corners from one free edge to the next.
#include "geometry/pattern/internal/free_edge_chains.h"

#include <map>
#include <optional>
#include <set>

#include "geometry/pattern/outline_segments.h"

namespace tp::geometry::internal {
namespace {

/// A span covering its whole edge (to within 0.5 mm at both ends).
bool whole(const Pattern& pattern, const EdgeSpan& s) {
  if (s.piece < 0 || s.piece >= static_cast<int>(pattern.pieces.size())) return false;
  const Piece& p = pattern.pieces[static_cast<size_t>(s.piece)];
  if (s.edge < 0 || s.edge >= static_cast<int>(p.edges.size())) return false;
  const double len = edge_length_mm(p.edges[static_cast<size_t>(s.edge)]);
  return s.from_mm <= 0.5 && (s.to_mm < 0 || s.to_mm >= len - 0.5);
}

}  // namespace

std::vector<FreeEdgeChain> free_edge_chains(const Pattern& pattern, const std::vector<Stitch>& stitches) {
  std::map<std::pair<int, int>, EdgeRef> partner;  // whole edge sewn to whole edge
  std::set<std::pair<int, int>> blocked;           // part of the edge sewn, or sewn start to start
  for (const Stitch& st : stitches) {
    if (!st.same_direction && whole(pattern, st.a) && whole(pattern, st.b)) {
      partner[{st.a.piece, st.a.edge}] = EdgeRef{st.b.piece, st.b.edge};
      partner[{st.b.piece, st.b.edge}] = EdgeRef{st.a.piece, st.a.edge};
    } else {
      blocked.insert({st.a.piece, st.a.edge});
      blocked.insert({st.b.piece, st.b.edge});
    }
  }
  auto edge_count = [&](int piece) {
    return static_cast<int>(pattern.pieces[static_cast<size_t>(piece)].edges.size());
  };
  auto is_free = [&](EdgeRef e) { return !partner.count({e.piece, e.edge}) && !blocked.count({e.piece, e.edge}); };
  int total = 0;
  for (int p = 0; p < static_cast<int>(pattern.pieces.size()); ++p) total += edge_count(p);
  // The free edge starting where `e` ends: round the corner across sewn edges.
  auto next = [&](EdgeRef e) -> std::optional<EdgeRef> {
    EdgeRef cur{e.piece, (e.edge + 1) % edge_count(e.piece)};
    for (int step = 0; step <= total; ++step) {
      if (is_free(cur)) return cur;
      auto it = partner.find({cur.piece, cur.edge});
      if (it == partner.end()) return std::nullopt;  // part of it sewn
      cur = EdgeRef{it->second.piece, (it->second.edge + 1) % edge_count(it->second.piece)};
    }
    return std::nullopt;
  };
  std::vector<EdgeRef> free;
  std::map<std::pair<int, int>, EdgeRef> succ;
  std::set<std::pair<int, int>> has_pred;
  for (int p = 0; p < static_cast<int>(pattern.pieces.size()); ++p)
    for (int e = 0; e < edge_count(p); ++e)
      if (is_free({p, e})) free.push_back({p, e});
  for (EdgeRef e : free)
    if (auto n = next(e); n && !has_pred.count({n->piece, n->edge})) {
      succ[{e.piece, e.edge}] = *n;
      has_pred.insert({n->piece, n->edge});
    }
  std::set<std::pair<int, int>> done;
  std::vector<FreeEdgeChain> out;
  auto walk = [&](EdgeRef start) {
    FreeEdgeChain c;
    EdgeRef cur = start;
    while (!done.count({cur.piece, cur.edge})) {
      done.insert({cur.piece, cur.edge});
      c.edges.push_back(cur);
      auto it = succ.find({cur.piece, cur.edge});
      if (it == succ.end()) break;
      if (it->second == start) c.closed = true;
      cur = it->second;
    }
    out.push_back(std::move(c));
  };
  for (EdgeRef e : free)  // open chains from their first edge
    if (!has_pred.count({e.piece, e.edge})) walk(e);
  for (EdgeRef e : free)  // then the loops
    if (!done.count({e.piece, e.edge})) walk(e);
  return out;
}

}  // namespace tp::geometry::internal
