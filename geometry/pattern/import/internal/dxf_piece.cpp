// geometry/pattern/internal/dxf_piece.cpp: AAMA layers of one block (outline, notches, grain, texts) to a piece.
#include "geometry/pattern/import/internal/dxf_piece.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "geometry/common/aama_layers.h"
#include "geometry/common/tolerances.h"
#include "geometry/pattern/curve.h"
#include "geometry/pattern/darts.h"
#include "geometry/pattern/import/dxf_aama.h"
#include "geometry/pattern/import/internal/outline_projection.h"
#include "geometry/pattern/internal/text.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/orient.h"
#include "geometry/pattern/outline_segments.h"
#include "geometry/pattern/role.h"

namespace tp::geometry::internal {
namespace {

/// Curve ends closer than this (mm) are joined when chaining lines into an outline.
constexpr double kChainTolerance_mm = 0.05;
/// A turn point marks the outline vertex within this distance (mm).
constexpr double kTurnPointTolerance_mm = 0.1;
/// Outline edges within this distance (mm) of the mirror line lie on the fold.
constexpr double kOnMirrorTolerance_mm = 0.5;
/// Default diameter (mm) of a drill hole given as a point.
constexpr double kDefaultDrill_mm = 3;
/// Bulges below this are straight segments.
constexpr double kStraightBulge = 1e-9;

/// A polyline in mm; bulge[i] curves the segment from pts[i] to pts[i + 1] (DXF bulge: tan of a
/// quarter of the arc's angle, positive counter-clockwise).
struct Polyline {
  std::vector<Vec2> pts;
  std::vector<double> bulge;
  bool closed = false;
};

Polyline reversed(const Polyline& p) {
  Polyline r;
  r.closed = p.closed;
  r.pts.assign(p.pts.rbegin(), p.pts.rend());
  size_t segs = p.closed ? p.pts.size() : p.pts.size() - 1;
  r.bulge.assign(p.pts.size(), 0);
  for (size_t i = 0; i < segs; ++i) {
    // Segment i (pts[i] -> pts[i+1]) becomes segment n-2-i of the reversed polyline, turning the
    // other way.
    size_t j = p.closed ? (p.pts.size() - 1 - ((i + 1) % p.pts.size())) : (p.pts.size() - 2 - i);
    r.bulge[j] = -p.bulge[i];
  }
  return r;
}

/// Segments of a polyline as flattened edges.
Result<std::vector<OutlineSegment>> segments_of(const Polyline& p, double tol) {
  std::vector<OutlineSegment> out;
  size_t n = p.pts.size();
  size_t segs = p.closed ? n : n - 1;
  for (size_t i = 0; i < segs; ++i) {
    Vec2 a = p.pts[i], b = p.pts[(i + 1) % n];
    double bulge = i < p.bulge.size() ? p.bulge[i] : 0;
    Edge e;
    if (std::abs(bulge) > kStraightBulge && norm(b - a) > 0) {
      // The arc's middle lies a sagitta of bulge * chord / 2 off the chord, to the right of
      // a -> b for a counter-clockwise (positive) bulge.
      Vec2 d = b - a;
      Vec2 mid = (a + b) * 0.5 - perp(d) * (bulge / 2);
      e = Edge{"", EdgeCurve::kArc, {Vec2{}, mid}, {}};
    } else {
      e = Edge{"", EdgeCurve::kLine, {}, {}};
    }
    Status s = flatten_edge(e, a, b, tol);
    if (!s) return std::unexpected(s.error());
    out.push_back(OutlineSegment{std::move(e), false});
  }
  return out;
}

std::vector<Vec2> flattened(const Polyline& p, double tol) {
  std::vector<Vec2> pts;
  auto segs = segments_of(p, tol);
  if (!segs || segs->empty()) return p.pts;
  pts.push_back(segs->front().edge.points_mm.front());
  for (const auto& s : *segs) pts.insert(pts.end(), s.edge.points_mm.begin() + 1, s.edge.points_mm.end());
  return pts;
}

/// Geometry of a block sorted by AAMA layer number.
struct Layers {
  std::map<int, std::vector<Polyline>> curves;
  std::map<int, std::vector<Vec2>> points;
  std::map<int, std::vector<std::pair<Vec2, double>>> circles;  // centre, radius (mm)
  std::vector<std::string> texts;
};

int layer_number(const DxfEntity& e) {
  std::string l = e.layer();
  if (l.empty() || l.size() > 4 || !std::all_of(l.begin(), l.end(), ::isdigit)) return -1;
  return std::stoi(l);
}

Layers sort_layers(const DxfBlock& block, double unit) {
  Layers L;
  for (const DxfEntity& e : block.entities) {
    int layer = layer_number(e);
    Vec2 p10{e.number(10) * unit, e.number(20) * unit};
    if (e.type == "TEXT" || e.type == "MTEXT" || e.type == "ATTRIB") {
      std::string t;
      for (const DxfGroup& g : e.groups)
        if (g.code == 3 || g.code == 1) t += g.value;
      // MTEXT paragraph breaks.
      for (size_t at; (at = t.find("\\P")) != std::string::npos;) t.replace(at, 2, "\n");
      L.texts.push_back(t);
      continue;
    }
    if (layer < 0) continue;
    if (e.type == "POINT") {
      L.points[layer].push_back(p10);
    } else if (e.type == "LINE") {
      Polyline p;
      p.pts = {p10, Vec2{e.number(11) * unit, e.number(21) * unit}};
      p.bulge = {0, 0};
      L.curves[layer].push_back(std::move(p));
    } else if (e.type == "POLYLINE") {
      Polyline p;
      p.closed = (static_cast<long>(e.number(70)) & 1) != 0;
      for (const DxfEntity& v : e.vertices) {
        // Spline frame control points (flag 16) are not on the curve.
        if ((static_cast<long>(v.number(70)) & 16) != 0) continue;
        p.pts.push_back({v.number(10) * unit, v.number(20) * unit});
        p.bulge.push_back(v.number(42));
      }
      if (!p.pts.empty()) L.curves[layer].push_back(std::move(p));
    } else if (e.type == "LWPOLYLINE") {
      Polyline p;
      p.closed = (static_cast<long>(e.number(70)) & 1) != 0;
      for (const DxfGroup& g : e.groups) {
        double v = std::strtod(g.value.c_str(), nullptr);
        if (!std::isfinite(v)) v = 0;
        if (g.code == 10) {
          p.pts.push_back({v * unit, 0});
          p.bulge.push_back(0);
        } else if (g.code == 20 && !p.pts.empty()) {
          p.pts.back().y = v * unit;
        } else if (g.code == 42 && !p.bulge.empty()) {
          p.bulge.back() = v;
        }
      }
      if (!p.pts.empty()) L.curves[layer].push_back(std::move(p));
    } else if (e.type == "ARC") {
      // Counter-clockwise from angle 50 to angle 51 (degrees) around 10/20 with radius 40.
      double r = e.number(40) * unit, a0 = e.number(50) * std::numbers::pi / 180,
             a1 = e.number(51) * std::numbers::pi / 180;
      double sweep = std::fmod(a1 - a0, 2 * std::numbers::pi);
      if (sweep <= 0) sweep += 2 * std::numbers::pi;
      if (!(r > 0) || !std::isfinite(sweep)) continue;
      Polyline p;
      p.pts = {p10 + Vec2{std::cos(a0), std::sin(a0)} * r, p10 + Vec2{std::cos(a1), std::sin(a1)} * r};
      p.bulge = {std::tan(sweep / 4), 0};
      L.curves[layer].push_back(std::move(p));
    } else if (e.type == "CIRCLE") {
      double r = e.number(40) * unit;
      if (r > 0 && std::isfinite(r)) L.circles[layer].push_back({p10, r});
    }
  }
  // A closed polyline that repeats its first point at the end has a zero-length last segment.
  for (auto& [layer, list] : L.curves)
    for (Polyline& p : list) {
      if (p.pts.size() > 2 && norm(p.pts.back() - p.pts.front()) <= kChainTolerance_mm) {
        p.pts.pop_back();
        p.bulge.pop_back();
        p.closed = true;
      }
      p.bulge.resize(p.pts.size(), 0);
    }
  return L;
}

/// Closed loops of a layer: its closed polylines plus open curves chained end to end.
std::vector<Polyline> loops_of(const std::vector<Polyline>& curves) {
  std::vector<Polyline> loops;
  std::vector<Polyline> open;
  for (const Polyline& p : curves) {
    if (p.closed && p.pts.size() >= 2) loops.push_back(p);
    else if (p.pts.size() >= 2) open.push_back(p);
  }
  std::vector<bool> used(open.size(), false);
  for (size_t s = 0; s < open.size(); ++s) {
    if (used[s]) continue;
    used[s] = true;
    Polyline chain = open[s];
    bool grew = true;
    while (grew && norm(chain.pts.back() - chain.pts.front()) > kChainTolerance_mm) {
      grew = false;
      for (size_t k = 0; k < open.size(); ++k) {
        if (used[k]) continue;
        Polyline next = open[k];
        if (norm(next.pts.back() - chain.pts.back()) <= kChainTolerance_mm) next = reversed(next);
        if (norm(next.pts.front() - chain.pts.back()) > kChainTolerance_mm) continue;
        used[k] = true;
        chain.bulge.pop_back();
        chain.pts.pop_back();
        chain.pts.insert(chain.pts.end(), next.pts.begin(), next.pts.end());
        chain.bulge.insert(chain.bulge.end(), next.bulge.begin(), next.bulge.end());
        grew = true;
        break;
      }
    }
    if (chain.pts.size() >= 3 && norm(chain.pts.back() - chain.pts.front()) <= kChainTolerance_mm) {
      chain.pts.pop_back();
      chain.bulge.pop_back();
      chain.closed = true;
      loops.push_back(std::move(chain));
    }
  }
  return loops;
}

double loop_area(const Polyline& p, double tol) { return signed_area(flattened(p, tol)); }

/// Where the line through a and b (a notch line, drawn square to the cut line) crosses the
/// outline nearest to a or b; distance_mm is from that end. Projection{} when it never does.
Projection cross_outline(const Piece& piece, Vec2 a, Vec2 b) {
  Projection best;
  Vec2 d = b - a;
  if (!(norm(d) > 0)) return best;
  for (int e = 0; e < static_cast<int>(piece.edges.size()); ++e) {
    const auto& pts = piece.edges[e].points_mm;
    double acc = 0;
    for (size_t i = 1; i < pts.size(); ++i) {
      Vec2 s = pts[i] - pts[i - 1];
      double len = norm(s);
      double den = cross(d, s);
      if (len > 0 && std::abs(den) > kParallelDeterminant * norm(d) * len) {
        double u = cross(pts[i - 1] - a, d) / den;  // along the outline segment
        if (u >= 0 && u <= 1) {
          Vec2 x = pts[i - 1] + s * u;
          double dist = std::min(norm(x - a), norm(x - b));
          if (dist < best.distance_mm) best = Projection{e, acc + u * len, dist};
        }
      }
      acc += len;
    }
  }
  return best;
}

std::string trim(std::string s) {
  auto sp = [](unsigned char c) { return std::isspace(c); };
  s.erase(s.begin(), std::find_if_not(s.begin(), s.end(), sp));
  s.erase(std::find_if_not(s.rbegin(), s.rend(), sp).base(), s.end());
  return s;
}

/// "Piece Name: Front" lines of the block's texts as KEY -> value (keys upper case, no spaces).
std::map<std::string, std::string> annotations(const std::vector<std::string>& texts) {
  std::map<std::string, std::string> out;
  for (const std::string& t : texts) {
    size_t start = 0;
    while (start <= t.size()) {
      size_t nl = t.find('\n', start);
      std::string line = t.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
      start = nl == std::string::npos ? t.size() + 1 : nl + 1;
      auto colon = line.find(':');
      if (colon == std::string::npos) continue;
      std::string key;
      for (char c : line.substr(0, colon))
        if (!std::isspace(static_cast<unsigned char>(c))) key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      out.emplace(key, trim(line.substr(colon + 1)));
    }
  }
  return out;
}

}  // namespace

Result<DxfPiece> build_dxf_piece(const DxfBlock& block, double unit, const std::string& file,
                                 const PatternImportOptions& options, std::vector<std::string>& warnings) {
  DxfPiece out;
  const double tol = options.chord_tolerance_mm;
  Layers L = sort_layers(block, unit);
  auto notes = annotations(L.texts);
  auto note = [&](std::initializer_list<const char*> keys) -> std::string {
    for (const char* k : keys)
      if (auto it = notes.find(k); it != notes.end() && !it->second.empty()) return it->second;
    return "";
  };
  Piece& piece = out.piece;
  piece.name = note({"PIECENAME", "PIECE", "NAME"});
  if (piece.name.empty()) piece.name = block.name;
  if (piece.name.empty()) piece.name = "piece" + std::to_string(block.line);
  const std::string who = file + ":" + std::to_string(block.line) + ": block '" + block.name + "'";

  bool has_sew = L.curves.count(14) > 0;
  bool has_boundary = L.curves.count(1) > 0;
  if (!has_sew && !has_boundary) return out;
  // The model's outline is the seam line: the sew line when given, else the boundary.
  const int outline_layer = aama_number(has_sew ? AamaLayer::kSewLines : AamaLayer::kBoundary);
  auto loops = loops_of(L.curves[outline_layer]);
  if (loops.empty())
    return fail(ErrorCode::kInvalidPattern, who + ": the " + std::string(has_sew ? "sew line (layer 14)" : "boundary (layer 1)") +
                                                " does not close");
  auto biggest = std::max_element(loops.begin(), loops.end(), [&](const Polyline& a, const Polyline& b) {
    return std::abs(loop_area(a, tol)) < std::abs(loop_area(b, tol));
  });
  Polyline loop = *biggest;
  if (loop_area(loop, tol) < 0) loop = reversed(loop);
  TP_TRY(segs, segments_of(loop, tol));
  // Turn points mark the corners of the boundary they were drawn for.
  bool use_turn_points = outline_layer == aama_number(AamaLayer::kBoundary) && !L.points[aama_number(AamaLayer::kTurnPoints)].empty();
  if (use_turn_points)
    for (OutlineSegment& s : segs)
      for (Vec2 tp : L.points[aama_number(AamaLayer::kTurnPoints)])
        if (norm(s.edge.points_mm.front() - tp) <= kTurnPointTolerance_mm) s.corner_before = true;
  piece.edges = edges_from_segments(std::move(segs), options.corner_angle_deg, !use_turn_points);
  if (piece.edges.empty()) return fail(ErrorCode::kInvalidPattern, who + ": the outline has no length");
  if (signed_area(outline(piece)) < 0) reverse_outline(piece);

  // Notches: a point, or a short line square to the cut line whose extension meets the outline.
  const double snap = has_sew ? kDxfNotchToSewLine_mm : kDxfNotchSnap_mm;
  std::vector<std::pair<Projection, Vec2>> found;
  for (Vec2 at : L.points[aama_number(AamaLayer::kNotches)]) found.push_back({project(piece, at), at});
  for (const Polyline& p : L.curves[aama_number(AamaLayer::kNotches)]) {
    Projection x = cross_outline(piece, p.pts.front(), p.pts.back());
    if (x.edge < 0) {
      Projection a = project(piece, p.pts.front()), b = project(piece, p.pts.back());
      x = a.distance_mm <= b.distance_mm ? a : b;
    }
    found.push_back({x, p.pts.front()});
  }
  for (const auto& [pr, at] : found) {
    if (pr.edge < 0 || pr.distance_mm > snap) {
      warnings.push_back(who + ": notch at " + internal::point(at) + " is not on the outline; ignored");
      continue;
    }
    piece.notches.push_back(Notch{"notch" + std::to_string(piece.notches.size() + 1), pr.edge, pr.position_mm, NotchType::kSlit});
  }
  if (!L.curves[aama_number(AamaLayer::kGrainLine)].empty()) {
    const Polyline& g = L.curves[aama_number(AamaLayer::kGrainLine)].front();
    if (norm(g.pts.back() - g.pts.front()) > 0) piece.grain = GrainLine{g.pts.front(), g.pts.back()};
  }
  if (!L.curves[aama_number(AamaLayer::kMirrorLine)].empty()) {
    const Polyline& m = L.curves[aama_number(AamaLayer::kMirrorLine)].front();
    Vec2 p = m.pts.front(), q = m.pts.back();
    std::vector<int> on;
    if (norm(q - p) > 0)
      for (int e = 0; e < static_cast<int>(piece.edges.size()); ++e) {
        const auto& pts = piece.edges[e].points_mm;
        if (std::all_of(pts.begin(), pts.end(), [&](Vec2 x) { return distance_to_line(x, p, q) <= kOnMirrorTolerance_mm; }))
          on.push_back(e);
      }
    if (on.size() == 1) piece.fold_edge = on.front();
    else warnings.push_back(who + ": mirror line matches " + std::to_string(on.size()) + " outline edges; piece kept as drawn");
  }
  for (int layer : {aama_number(AamaLayer::kInternalLines), aama_number(AamaLayer::kInternalCutouts)})
    for (const Polyline& p : L.curves[layer]) {
      std::string base = layer == aama_number(AamaLayer::kInternalLines) ? "line" : "cutout";
      piece.internal_lines.push_back(InternalLine{base + std::to_string(piece.internal_lines.size() + 1), flattened(p, tol)});
    }
  for (Vec2 p : L.points[aama_number(AamaLayer::kDrillHoles)]) piece.drill_holes.push_back(DrillHole{p, kDefaultDrill_mm});
  for (const auto& [c, r] : L.circles[aama_number(AamaLayer::kDrillHoles)]) piece.drill_holes.push_back(DrillHole{c, 2 * r});
  detect_darts(piece);

  std::string qty = note({"QUANTITY", "QTY"});
  if (!qty.empty()) {
    char* end = nullptr;
    long q = std::strtol(qty.c_str(), &end, 10);
    if (end != qty.c_str() && q >= 1 && q <= 1000) out.quantity = static_cast<int>(q);
    else warnings.push_back(who + ": quantity '" + qty + "' is not a number from 1 to 1000; cut once");
  }
  std::string mirror = note({"MIRROR", "PAIR", "FLIP"});
  if (!mirror.empty()) {
    char c = static_cast<char>(std::toupper(static_cast<unsigned char>(mirror.front())));
    out.mirror_pairs = c == 'Y' || c == 'T' || c == '1';
  }
  if (out.mirror_pairs && out.quantity % 2 != 0) {
    warnings.push_back(who + ": mirrored pairs need an even quantity; cut as identical copies");
    out.mirror_pairs = false;
  }
  piece.material = note({"MATERIAL", "FABRIC"});
  out.size = note({"SIZE", "SAMPLESIZE"});
  std::string category = note({"CATEGORY"});
  piece.role = guess_role(category);
  if (piece.role.empty()) piece.role = guess_role(piece.name);
  return out;
}

}  // namespace tp::geometry::internal
