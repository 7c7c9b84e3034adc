// geometry/mesh/sample_boundary.cpp: seam-aware sampling of piece outlines (matched stitch spans).
#include "geometry/mesh/sample_boundary.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

// Span ends closer than this along one edge are the same breakpoint.
constexpr double kBreakpointTolMm = 0.05;
// A span may end this far past its edge's end (rounding in importers) and is clamped.
constexpr double kSpanOverrunTolMm = 0.5;

struct SpanNode {
  int piece = 0, edge = 0;
  double from_mm = 0, to_mm = 0;
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

std::string edge_label(const Pattern& p, int piece, int edge) {
  return "piece '" + p.pieces[piece].name + "' edge '" + p.pieces[piece].edges[edge].name + "'";
}

}  // namespace

Vec2 point_at_arc_length(const std::vector<Vec2>& pl, double s_mm) {
  if (pl.empty()) return {};
  if (s_mm <= 0) return pl.front();
  double acc = 0;
  for (size_t i = 1; i < pl.size(); ++i) {
    double seg = norm(pl[i] - pl[i - 1]);
    if (acc + seg >= s_mm && seg > 0) return pl[i - 1] + (pl[i] - pl[i - 1]) * ((s_mm - acc) / seg);
    acc += seg;
  }
  return pl.back();
}

Result<BoundarySampling> sample_boundary(const Pattern& pattern, double target_edge_mm) {
  if (!(target_edge_mm > 0)) return fail(ErrorCode::kInvalidArgument, "target edge length must be > 0 mm");
  const int np = static_cast<int>(pattern.pieces.size());

  // Edge lengths, with degenerate edges rejected up front.
  std::vector<std::vector<double>> len(np);
  for (int p = 0; p < np; ++p) {
    const Piece& piece = pattern.pieces[p];
    if (piece.edges.size() < 2)
      return fail(ErrorCode::kInvalidPattern, "piece '" + piece.name + "' has fewer than 2 edges");
    for (size_t e = 0; e < piece.edges.size(); ++e) {
      double l = edge_length_mm(piece.edges[e]);
      if (piece.edges[e].points_mm.size() < 2 || !(l > kBreakpointTolMm))
        return fail(ErrorCode::kInvalidPattern, edge_label(pattern, p, static_cast<int>(e)) + " has zero length");
      len[p].push_back(l);
    }
  }

  // Resolve every stitch span to [from, to] in mm and index it as a node.
  std::vector<SpanNode> nodes;
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    for (const EdgeSpan* sp : {&pattern.stitches[s].a, &pattern.stitches[s].b}) {
      std::string where = "stitch " + std::to_string(s);
      if (sp->piece < 0 || sp->piece >= np)
        return fail(ErrorCode::kUnknownReference, where + ": unknown piece index " + std::to_string(sp->piece));
      const Piece& piece = pattern.pieces[sp->piece];
      if (sp->edge < 0 || sp->edge >= static_cast<int>(piece.edges.size()))
        return fail(ErrorCode::kUnknownReference,
                    where + ": piece '" + piece.name + "' has no edge " + std::to_string(sp->edge));
      double l = len[sp->piece][sp->edge];
      double to = sp->to_mm < 0 ? l : sp->to_mm;
      if (sp->from_mm < 0 || to > l + kSpanOverrunTolMm || to - sp->from_mm < kBreakpointTolMm)
        return fail(ErrorCode::kInvalidPattern,
                    where + ": span [" + std::to_string(sp->from_mm) + ", " + std::to_string(to) + "] mm does not fit " +
                        edge_label(pattern, sp->piece, sp->edge) + " of length " + std::to_string(l) + " mm");
      nodes.push_back({sp->piece, sp->edge, sp->from_mm, std::min(to, l)});
    }
  }

  // Spans that are the same piece of edge (a span sewn twice) form one node.
  std::vector<int> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < nodes.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (nodes[i].piece == nodes[j].piece && nodes[i].edge == nodes[j].edge &&
          std::abs(nodes[i].from_mm - nodes[j].from_mm) < kBreakpointTolMm &&
          std::abs(nodes[i].to_mm - nodes[j].to_mm) < kBreakpointTolMm)
        parent[find_root(parent, static_cast<int>(i))] = find_root(parent, static_cast<int>(j));
  // The two spans of a stitch share a subdivision count.
  for (size_t s = 0; s < pattern.stitches.size(); ++s)
    parent[find_root(parent, static_cast<int>(2 * s))] = find_root(parent, static_cast<int>(2 * s + 1));
  std::vector<int> group_n(nodes.size(), 1);
  for (size_t i = 0; i < nodes.size(); ++i) {
    int r = find_root(parent, static_cast<int>(i));
    int n = static_cast<int>(std::ceil((nodes[i].to_mm - nodes[i].from_mm) / target_edge_mm - kCeilSlack));
    group_n[r] = std::max(group_n[r], std::max(n, 1));
  }

  BoundarySampling out;
  out.pieces.resize(np);
  // Ring index of each span node's first vertex, to read stitch vertices afterwards.
  std::vector<int> node_first(nodes.size(), -1), node_count(nodes.size(), 0);
  for (int p = 0; p < np; ++p) {
    const Piece& piece = pattern.pieces[p];
    PieceBoundary& pb = out.pieces[p];
    const int ne = static_cast<int>(piece.edges.size());
    pb.edge_vertices.resize(ne);
    for (int e = 0; e < ne; ++e) {
      const double l = len[p][e];
      // Breakpoints: edge ends plus every span end on this edge.
      std::vector<double> bps{0.0, l};
      std::vector<int> here;
      for (size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].piece == p && nodes[i].edge == e) {
          here.push_back(static_cast<int>(i));
          bps.push_back(nodes[i].from_mm);
          bps.push_back(nodes[i].to_mm);
        }
      std::sort(bps.begin(), bps.end());
      std::vector<double> uniq;
      for (double b : bps)
        if (uniq.empty() || b - uniq.back() > kBreakpointTolMm) uniq.push_back(b);
      uniq.back() = l;

      pb.edge_vertices[e].push_back(static_cast<int>(pb.ring_mm.size()));
      for (size_t k = 0; k + 1 < uniq.size(); ++k) {
        const double s0 = uniq[k], s1 = uniq[k + 1];
        // Which span covers this segment, if any; two different spans mean they overlap.
        int covering = -1;
        for (int i : here) {
          if (nodes[i].from_mm < s1 - kBreakpointTolMm && nodes[i].to_mm > s0 + kBreakpointTolMm) {
            bool exact = std::abs(nodes[i].from_mm - s0) < kBreakpointTolMm && std::abs(nodes[i].to_mm - s1) < kBreakpointTolMm;
            int root = find_root(parent, i);
            if (!exact || (covering >= 0 && find_root(parent, covering) != root))
              return fail(ErrorCode::kMeshing, edge_label(pattern, p, e) + ": stitched spans overlap near " +
                                                   std::to_string(s0) + " mm");
            covering = i;
          }
        }
        int n = covering >= 0 ? group_n[find_root(parent, covering)]
                              : std::max(1, static_cast<int>(std::ceil((s1 - s0) / target_edge_mm - kCeilSlack)));
        if (covering >= 0)
          for (int i : here)
            if (find_root(parent, i) == find_root(parent, covering) && std::abs(nodes[i].from_mm - s0) < kBreakpointTolMm) {
              node_first[i] = static_cast<int>(pb.ring_mm.size());
              node_count[i] = n + 1;
            }
        // Sample [s0, s1) uniformly in arc length; s1 is the next segment's (or edge's) start.
        for (int j = 0; j < n; ++j) {
          if (k > 0 || j > 0) pb.edge_vertices[e].push_back(static_cast<int>(pb.ring_mm.size()));
          pb.ring_mm.push_back(point_at_arc_length(piece.edges[e].points_mm, s0 + (s1 - s0) * j / n));
        }
      }
    }
    // Each edge ends at the next edge's first vertex (the last edge at ring vertex 0).
    for (int e = 0; e < ne; ++e) pb.edge_vertices[e].push_back(e + 1 < ne ? pb.edge_vertices[e + 1].front() : 0);
  }

  // Matched vertex pairs per stitch, from span a's start to its end.
  const auto ring_index = [&](int node, int j) {
    const PieceBoundary& pb = out.pieces[nodes[node].piece];
    return (node_first[node] + j) % static_cast<int>(pb.ring_mm.size());
  };
  out.stitch_pairs.resize(pattern.stitches.size());
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    int na = static_cast<int>(2 * s), nb = static_cast<int>(2 * s + 1);
    if (node_first[na] < 0 || node_first[nb] < 0 || node_count[na] != node_count[nb])
      return fail(ErrorCode::kMeshing, "stitch " + std::to_string(s) + ": spans could not be sampled alike");
    const int m = node_count[na];
    for (int j = 0; j < m; ++j) {
      int jb = pattern.stitches[s].same_direction ? j : m - 1 - j;
      out.stitch_pairs[s].push_back({ring_index(na, j), ring_index(nb, jb)});
    }
  }
  return out;
}

}  // namespace tp::geometry
