// geometry/pattern/pattern_json_write.cpp: writing the native JSON pattern format (physical pieces, mm).
#include <nlohmann/json.hpp>

#include <fstream>

#include "geometry/pattern/pattern_json.h"

namespace tp::geometry {
namespace {

using ojson = nlohmann::ordered_json;

ojson pt(Vec2 p) { return ojson::array({p.x, p.y}); }

ojson pts(const std::vector<Vec2>& ps) {
  ojson a = ojson::array();
  for (Vec2 p : ps) a.push_back(pt(p));
  return a;
}

const char* curve_name(EdgeCurve c) {
  switch (c) {
    case EdgeCurve::kLine: return "line";
    case EdgeCurve::kQuadratic: return "quadratic";
    case EdgeCurve::kCubic: return "cubic";
    case EdgeCurve::kArc: return "arc";
    case EdgeCurve::kPolyline: return "polyline";
  }
  return "line";
}

const char* notch_name(NotchType t) {
  switch (t) {
    case NotchType::kSlit: return "slit";
    case NotchType::kV: return "v";
    case NotchType::kT: return "t";
    case NotchType::kU: return "u";
  }
  return "slit";
}

ojson edge_json(const Edge& e) {
  ojson j;
  j["name"] = e.name;
  j["from"] = pt(e.points_mm.empty() ? Vec2{} : e.points_mm.front());
  if (e.curve != EdgeCurve::kLine) j["curve"] = curve_name(e.curve);
  switch (e.curve) {
    case EdgeCurve::kLine:
      break;
    case EdgeCurve::kQuadratic:
    case EdgeCurve::kCubic:
      j["controls"] = pts(e.control_mm);
      break;
    case EdgeCurve::kArc:
      j["through"] = pt(e.control_mm.size() == 2 ? e.control_mm[1] : Vec2{});
      break;
    case EdgeCurve::kPolyline: {
      std::vector<Vec2> inner;
      for (size_t i = 1; i + 1 < e.points_mm.size(); ++i) inner.push_back(e.points_mm[i]);
      j["points"] = pts(inner);
      break;
    }
  }
  return j;
}

ojson piece_json(const Piece& p) {
  ojson j;
  j["name"] = p.name;
  if (!p.role.empty()) j["role"] = p.role;
  if (!p.material.empty()) j["material"] = p.material;
  if (!p.source_piece.empty() && p.source_piece != p.name) j["source_piece"] = p.source_piece;
  if (p.mirrored) j["mirrored"] = true;
  ojson edges = ojson::array();
  for (const Edge& e : p.edges) edges.push_back(edge_json(e));
  j["edges"] = std::move(edges);
  if (p.fold_edge && *p.fold_edge >= 0 && *p.fold_edge < static_cast<int>(p.edges.size()))
    j["fold"] = p.edges[*p.fold_edge].name;
  if (p.fold_line_mm) j["fold_line"] = ojson::array({pt((*p.fold_line_mm)[0]), pt((*p.fold_line_mm)[1])});
  if (!p.notches.empty()) {
    ojson a = ojson::array();
    for (const Notch& n : p.notches) {
      ojson nj;
      if (!n.name.empty()) nj["name"] = n.name;
      nj["edge"] = n.edge >= 0 && n.edge < static_cast<int>(p.edges.size()) ? p.edges[n.edge].name : "";
      nj["at"] = n.position_mm;
      if (n.type != NotchType::kSlit) nj["type"] = notch_name(n.type);
      a.push_back(std::move(nj));
    }
    j["notches"] = std::move(a);
  }
  if (p.grain) j["grain"] = ojson::array({pt(p.grain->from_mm), pt(p.grain->to_mm)});
  if (!p.internal_lines.empty()) {
    ojson a = ojson::array();
    for (const InternalLine& l : p.internal_lines) a.push_back(ojson{{"name", l.name}, {"points", pts(l.points_mm)}});
    j["internal_lines"] = std::move(a);
  }
  if (!p.darts.empty()) {
    ojson a = ojson::array();
    auto en = [&](int e) { return e >= 0 && e < static_cast<int>(p.edges.size()) ? p.edges[e].name : std::string(); };
    for (const Dart& d : p.darts) a.push_back(ojson{{"name", d.name}, {"legs", ojson::array({en(d.leg_a), en(d.leg_b)})}});
    j["darts"] = std::move(a);
  }
  if (!p.drill_holes.empty()) {
    ojson a = ojson::array();
    for (const DrillHole& h : p.drill_holes) a.push_back(ojson{{"at", pt(h.position_mm)}, {"diameter", h.diameter_mm}});
    j["drill_holes"] = std::move(a);
  }
  if (p.placement) {
    ojson r = ojson::array();
    for (double v : p.placement->rotation) r.push_back(v);
    const Vec3& t = p.placement->translation_mm;
    j["placement"] = ojson{{"translation", ojson::array({t.x, t.y, t.z})}, {"rotation", std::move(r)}};
  }
  return j;
}

ojson side_json(const Pattern& pat, const EdgeSpan& s) {
  ojson j;
  bool ok = s.piece >= 0 && s.piece < static_cast<int>(pat.pieces.size());
  const Piece* p = ok ? &pat.pieces[s.piece] : nullptr;
  j["piece"] = p ? p->name : "";
  j["edge"] = p && s.edge >= 0 && s.edge < static_cast<int>(p->edges.size()) ? p->edges[s.edge].name : "";
  if (s.from_mm > 0) j["from"] = s.from_mm;
  if (s.to_mm >= 0) j["to"] = s.to_mm;
  return j;
}

}  // namespace

std::string write_pattern_json(const Pattern& pattern) {
  ojson root;
  root["format"] = "tp-pattern";
  root["version"] = 1;
  if (!pattern.name.empty()) root["name"] = pattern.name;
  if (!pattern.size.empty()) root["size"] = pattern.size;
  root["units"] = "mm";
  ojson pieces = ojson::array();
  for (const Piece& p : pattern.pieces) pieces.push_back(piece_json(p));
  root["pieces"] = std::move(pieces);
  ojson stitches = ojson::array();
  for (const Stitch& s : pattern.stitches) {
    ojson j{{"a", side_json(pattern, s.a)}, {"b", side_json(pattern, s.b)}};
    if (s.same_direction) j["same_direction"] = true;
    if (s.ease_ratio > 0) j["ease"] = s.ease_ratio;
    stitches.push_back(std::move(j));
  }
  root["stitches"] = std::move(stitches);
  return root.dump(1) + "\n";
}

Status save_pattern_json(const Pattern& pattern, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return fail(ErrorCode::kIo, path.string() + ": cannot open for writing");
  out << write_pattern_json(pattern);
  out.close();
  if (!out) return fail(ErrorCode::kIo, path.string() + ": write failed");
  return {};
}

}  // namespace tp::geometry
