// geometry/allowance/allowance_widths.cpp: resolves allowance widths and corner styles per edge.
#include "geometry/allowance/allowance_widths.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace tp::geometry {
namespace {

bool name_says_hem(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower.find("hem") != std::string::npos;
}

Status check_width(double w, const std::string& field) {
  if (!std::isfinite(w) || w < 0)
    return fail(ErrorCode::kInvalidArgument, field + " must be a finite width >= 0 mm, got " + std::to_string(w));
  return {};
}

Status check_ref(const Pattern& pattern, const std::string& piece, const std::string& edge, const std::string& field) {
  const int p = find_piece(pattern, piece);
  if (p < 0) return fail(ErrorCode::kUnknownReference, field + ".piece: no piece named '" + piece + "'");
  if (find_edge(pattern.pieces[static_cast<size_t>(p)], edge) < 0)
    return fail(ErrorCode::kUnknownReference, field + ".edge: piece '" + piece + "' has no edge named '" + edge + "'");
  return {};
}

}  // namespace

Status validate_finishing(const Pattern& pattern, const Finishing& f) {
  for (auto [w, field] : {std::pair{f.seam_allowance_mm, "finishing.seam_allowance_mm"},
                          std::pair{f.hem_allowance_mm, "finishing.hem_allowance_mm"},
                          std::pair{f.edge_allowance_mm, "finishing.edge_allowance_mm"},
                          std::pair{f.notch_depth_mm, "finishing.notch_depth_mm"},
                          std::pair{f.notch_width_mm, "finishing.notch_width_mm"}})
    if (auto st = check_width(w, field); !st) return st;
  if (!std::isfinite(f.mitre_limit) || f.mitre_limit < 1)
    return fail(ErrorCode::kInvalidArgument, "finishing.mitre_limit must be >= 1, got " + std::to_string(f.mitre_limit));
  if (!std::isfinite(f.label_height_mm) || f.label_height_mm <= 0)
    return fail(ErrorCode::kInvalidArgument, "finishing.label_height_mm must be > 0");
  for (size_t i = 0; i < f.edge_widths.size(); ++i) {
    const std::string field = "finishing.edge_widths[" + std::to_string(i) + "]";
    if (auto st = check_ref(pattern, f.edge_widths[i].piece, f.edge_widths[i].edge, field); !st) return st;
    if (auto st = check_width(f.edge_widths[i].width_mm, field + ".width_mm"); !st) return st;
  }
  for (size_t i = 0; i < f.hem_edges.size(); ++i)
    if (auto st = check_ref(pattern, f.hem_edges[i].piece, f.hem_edges[i].edge, "finishing.hem_edges[" + std::to_string(i) + "]"); !st)
      return st;
  for (size_t i = 0; i < f.corners.size(); ++i)
    if (auto st = check_ref(pattern, f.corners[i].piece, f.corners[i].edge, "finishing.corners[" + std::to_string(i) + "]"); !st)
      return st;
  return {};
}

Result<PieceAllowance> resolve_allowance(const Pattern& pattern, int piece, const Finishing& f) {
  if (piece < 0 || piece >= static_cast<int>(pattern.pieces.size()))
    return fail(ErrorCode::kInvalidArgument, "resolve_allowance: no piece " + std::to_string(piece));
  if (auto st = validate_finishing(pattern, f); !st) return std::unexpected(st.error());
  const Piece& pc = pattern.pieces[static_cast<size_t>(piece)];
  const size_t n = pc.edges.size();
  PieceAllowance out;
  out.width_mm.assign(n, f.edge_allowance_mm);
  out.sewn.assign(n, false);
  out.hem.assign(n, false);
  out.corner.assign(n, f.seam_corner);
  for (const Stitch& s : pattern.stitches)
    for (const EdgeSpan* sp : {&s.a, &s.b})
      if (sp->piece == piece && sp->edge >= 0 && static_cast<size_t>(sp->edge) < n) out.sewn[static_cast<size_t>(sp->edge)] = true;
  for (size_t e = 0; e < n; ++e) out.hem[e] = !out.sewn[e] && name_says_hem(pc.edges[e].name);
  for (const EdgeAllowance& h : f.hem_edges)
    if (h.piece == pc.name) out.hem[static_cast<size_t>(find_edge(pc, h.edge))] = true;
  for (size_t e = 0; e < n; ++e) {
    if (out.hem[e]) out.width_mm[e] = f.hem_allowance_mm;
    else if (out.sewn[e]) out.width_mm[e] = f.seam_allowance_mm;
  }
  // A half piece kept on the fold is cut on the fold line itself.
  if (pc.fold_edge && *pc.fold_edge >= 0 && static_cast<size_t>(*pc.fold_edge) < n) out.width_mm[static_cast<size_t>(*pc.fold_edge)] = 0;
  for (const EdgeAllowance& o : f.edge_widths)
    if (o.piece == pc.name) out.width_mm[static_cast<size_t>(find_edge(pc, o.edge))] = o.width_mm;
  if (f.reflect_hem_corners) {
    for (size_t e = 0; e < n; ++e) {
      const size_t next = (e + 1) % n;
      if (out.hem[e] && !out.hem[next]) out.corner[e] = CornerStyle::kReflectIncoming;
      else if (out.hem[next] && !out.hem[e]) out.corner[e] = CornerStyle::kReflectOutgoing;
    }
  }
  for (const CornerOverride& c : f.corners)
    if (c.piece == pc.name) out.corner[static_cast<size_t>(find_edge(pc, c.edge))] = c.style;
  return out;
}

}  // namespace tp::geometry
