// geometry/pattern/internal/svg_piece.cpp: one FreeSewing part (paths, notches, notes, texts) to a drafted piece.
#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry/pattern/curve.h"
#include "geometry/pattern/darts.h"
#include "geometry/pattern/import/freesewing_svg.h"
#include "geometry/pattern/import/internal/outline_projection.h"
#include "geometry/pattern/import/internal/svg_part.h"
#include "geometry/pattern/import/svg_path.h"
#include "geometry/pattern/internal/text.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/orient.h"
#include "geometry/pattern/outline_segments.h"
#include "geometry/pattern/role.h"

namespace tp::geometry::internal {
namespace {

/// A subpath whose end is this close (mm) to its start is closed even without a Z.
constexpr double kClosureTolerance_mm = 0.01;
/// Outline edges within this distance (mm) of the cut-on-fold line lie on the fold.
constexpr double kOnFoldTolerance_mm = 0.5;
/// Classes FreeSewing gives seam lines, one per material.
const char* const kMaterials[] = {"fabric", "lining", "interfacing", "canvas", "various"};

std::vector<std::string> class_tokens(const std::string& cls) {
  std::vector<std::string> out;
  std::istringstream in(cls);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& w) { return std::find(v.begin(), v.end(), w) != v.end(); }

/// The map from part coordinates (y down) to piece coordinates (y up).
const Affine2 kFlipY = Affine2::scale(1, -1);

/// Segments of one subpath as flattened edges in piece coordinates.
Result<std::vector<OutlineSegment>> subpath_segments(const SvgSubpath& sp, const Affine2& m, double tol) {
  std::vector<OutlineSegment> out;
  auto add = [&](Edge e, Vec2 a, Vec2 b) -> Status {
    for (Vec2& c : e.control_mm) c = m.apply(c);
    Status s = flatten_edge(e, m.apply(a), m.apply(b), tol);
    if (!s) return s;
    out.push_back(OutlineSegment{std::move(e), false});
    return {};
  };
  for (const SvgSegment& s : sp.segments) {
    switch (s.kind) {
      case SvgSegment::Kind::kLine:
        TP_CHECK(add(Edge{"", EdgeCurve::kLine, {}, {}}, s.from, s.to));
        break;
      case SvgSegment::Kind::kQuadratic:
        TP_CHECK(add(Edge{"", EdgeCurve::kQuadratic, {s.c1}, {}}, s.from, s.to));
        break;
      case SvgSegment::Kind::kCubic:
        TP_CHECK(add(Edge{"", EdgeCurve::kCubic, {s.c1, s.c2}, {}}, s.from, s.to));
        break;
      case SvgSegment::Kind::kArc: {
        // Elliptical arcs become cubic chains well inside the chord tolerance.
        Vec2 a = s.from;
        for (const auto& c : svg_arc_to_cubics(s, tol / 10)) {
          TP_CHECK(add(Edge{"", EdgeCurve::kCubic, {c[0], c[1]}, {}}, a, c[2]));
          a = c[2];
        }
        break;
      }
    }
  }
  return out;
}

/// Polyline of a subpath in piece coordinates (for internal lines and note markers).
Result<std::vector<Vec2>> subpath_points(const SvgSubpath& sp, const Affine2& m, double tol) {
  TP_TRY(segs, subpath_segments(sp, m, tol));
  std::vector<Vec2> pts{m.apply(sp.start)};
  for (const OutlineSegment& s : segs) pts.insert(pts.end(), s.edge.points_mm.begin() + 1, s.edge.points_mm.end());
  return pts;
}

/// "cut,2,...:mirrored,...:from,...:fabric" -> quantity, mirrored pairs, material.
void read_annotations(const std::vector<std::string>& texts, SvgPiece& out) {
  for (const std::string& t : texts) {
    std::vector<std::string> items;
    std::string cur;
    for (char c : t) {
      if (c == ',') {
        items.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    items.push_back(cur);
    auto bare = [](std::string s) {
      auto colon = s.rfind(':');
      if (colon != std::string::npos) s = s.substr(colon + 1);
      s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
      return s;
    };
    for (size_t i = 0; i < items.size(); ++i) {
      std::string w = bare(items[i]);
      if (w == "cut" && i + 1 < items.size()) {
        std::string n = bare(items[i + 1]);
        if (!n.empty() && n.size() < 5 && std::all_of(n.begin(), n.end(), ::isdigit)) out.quantity = std::stoi(n);
      } else if (w == "mirrored") {
        out.mirror_pairs = true;
      } else if (w == "from" && i + 1 < items.size()) {
        std::string m = bare(items[i + 1]);
        if (!m.empty()) out.piece.material = m;
      }
    }
  }
}

}  // namespace

Result<SvgPiece> build_svg_piece(const SvgPart& part, const std::string& file, const PatternImportOptions& options,
                                 std::vector<std::string>& warnings) {
  SvgPiece out;
  Piece& piece = out.piece;
  piece.name = part.name;
  piece.role = guess_role(part.name);
  const double tol = options.chord_tolerance_mm;
  auto where = [&](int line) { return file + ":" + std::to_string(line) + ": part '" + part.name + "'"; };

  // The seam line: the closed subpath of largest area among the material paths that are not
  // cut lines. The other material paths are lines drawn on the piece (hem fold lines).
  struct Candidate {
    std::vector<OutlineSegment> segs;
    double area = 0;
    std::string material;
    int line = 0;
  };
  std::optional<Candidate> seam;
  std::vector<InternalLine> lines;
  for (const SvgPathElement& pe : part.paths) {
    auto cls = class_tokens(pe.cls);
    const char* material = nullptr;
    for (const char* m : kMaterials)
      if (has(cls, m)) material = m;
    if (!material || has(cls, "sa") || has(cls, "hidden") || has(cls, "help")) continue;
    auto subpaths = parse_svg_path(pe.d);
    if (!subpaths)
      return std::unexpected(Error{ErrorCode::kParse, where(pe.line) + ": path '" + pe.id + "': " + subpaths.error().message});
    const Affine2 m = kFlipY.compose(pe.to_part);
    for (const SvgSubpath& sp : *subpaths) {
      if (sp.segments.empty()) continue;
      TP_TRY(segs, subpath_segments(sp, m, tol));
      if (segs.empty()) continue;
      Vec2 start = segs.front().edge.points_mm.front(), end = segs.back().edge.points_mm.back();
      bool closed = sp.closed || norm(end - start) <= kClosureTolerance_mm;
      if (closed) {
        // Close a tiny gap exactly so the outline joins up.
        segs.back().edge.points_mm.back() = start;
        Polygon poly;
        for (const auto& s : segs) poly.insert(poly.end(), s.edge.points_mm.begin(), s.edge.points_mm.end() - 1);
        double area = signed_area(poly);
        if (!seam || std::abs(area) > std::abs(seam->area)) {
          if (seam) {
            InternalLine l{"line" + std::to_string(lines.size() + 1), {}};
            for (const auto& s : seam->segs) l.points_mm.insert(l.points_mm.end(), s.edge.points_mm.begin(), s.edge.points_mm.end());
            lines.push_back(std::move(l));
          }
          seam = Candidate{std::move(segs), area, material, pe.line};
          continue;
        }
      }
      InternalLine l{"line" + std::to_string(lines.size() + 1), {}};
      l.points_mm.push_back(start);
      for (const auto& s : segs) l.points_mm.insert(l.points_mm.end(), s.edge.points_mm.begin() + 1, s.edge.points_mm.end());
      lines.push_back(std::move(l));
    }
  }
  if (!seam) {
    warnings.push_back(where(part.line) + ": no closed seam line; part skipped");
    return out;
  }
  piece.material = seam->material;
  piece.edges = edges_from_segments(std::move(seam->segs), options.corner_angle_deg);
  piece.internal_lines = std::move(lines);
  // y was flipped, so FreeSewing's clockwise-on-screen outlines arrive counter-clockwise and
  // vice versa; either way the piece ends up counter-clockwise.
  if (signed_area(outline(piece)) < 0) reverse_outline(piece);

  // Notes: the grain line and the cut-on-fold line (from the first to the last point of the
  // marker path, which FreeSewing draws as a bracket off the fold).
  std::optional<std::array<Vec2, 2>> fold;
  for (const SvgPathElement& pe : part.paths) {
    bool is_fold = pe.marker_start.find("cutonfold") != std::string::npos ||
                   pe.data_text.find("cutOnFold") != std::string::npos;
    bool is_grain = pe.marker_start.find("grainline") != std::string::npos ||
                    pe.data_text.find("rainline") != std::string::npos;
    if (!is_fold && !is_grain) continue;
    auto subpaths = parse_svg_path(pe.d);
    if (!subpaths || subpaths->empty()) {
      warnings.push_back(where(pe.line) + ": unreadable marker path '" + pe.id + "' ignored");
      continue;
    }
    TP_TRY(pts, subpath_points(subpaths->front(), kFlipY.compose(pe.to_part), tol));
    if (pts.size() < 2 || norm(pts.back() - pts.front()) <= 0) continue;
    if (is_fold) fold = std::array<Vec2, 2>{pts.front(), pts.back()};
    if (is_grain) piece.grain = GrainLine{pts.front(), pts.back()};
  }
  if (fold) {
    std::vector<int> on;
    for (int e = 0; e < static_cast<int>(piece.edges.size()); ++e) {
      const auto& pts = piece.edges[e].points_mm;
      if (std::all_of(pts.begin(), pts.end(), [&](Vec2 x) { return distance_to_line(x, (*fold)[0], (*fold)[1]) <= kOnFoldTolerance_mm; }))
        on.push_back(e);
    }
    if (on.size() == 1) piece.fold_edge = on.front();
    else
      warnings.push_back(where(part.line) + ": cut-on-fold marker matches " + std::to_string(on.size()) +
                         " seam edges; the piece is kept as drawn");
  }

  // Notches on the seam line; marks inside the piece become drill marks.
  for (const SvgNotchMark& n : part.notches) {
    Vec2 at = kFlipY.apply(n.at);
    Projection pr = project(piece, at);
    if (pr.edge < 0 || pr.distance_mm > kSvgNotchSnap_mm) {
      piece.drill_holes.push_back(DrillHole{at, 0});
      continue;
    }
    std::string name = (n.double_notch ? "bnotch" : "notch") + std::to_string(piece.notches.size() + 1);
    if (!n.double_notch) {
      piece.notches.push_back(Notch{name, pr.edge, pr.position_mm, NotchType::kSlit});
    } else {
      double len = edge_length_mm(piece.edges[pr.edge]);
      double a = std::clamp(pr.position_mm - kDoubleNotchSpacing_mm / 2, 0.0, len);
      double b = std::clamp(pr.position_mm + kDoubleNotchSpacing_mm / 2, 0.0, len);
      piece.notches.push_back(Notch{name + "a", pr.edge, a, NotchType::kSlit});
      piece.notches.push_back(Notch{name + "b", pr.edge, b, NotchType::kSlit});
    }
  }
  detect_darts(piece);
  read_annotations(part.texts, out);
  if (out.mirror_pairs && out.quantity % 2 != 0) {
    warnings.push_back(where(part.line) + ": 'mirrored' with an odd quantity " + std::to_string(out.quantity) +
                       "; cut as identical copies");
    out.mirror_pairs = false;
  }
  if (out.quantity < 1) out.quantity = 1;
  return out;
}

}  // namespace tp::geometry::internal
