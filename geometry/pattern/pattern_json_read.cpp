// geometry/pattern/pattern_json_read.cpp: reading the native JSON pattern format.
#include <map>
#include <set>

#include "geometry/pattern/internal/json_fields.h"
#include "geometry/pattern/internal/pattern_json_stitches.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/orient.h"
#include "geometry/pattern/pattern_json.h"
#include "geometry/pattern/placement.h"
#include "geometry/pattern/unfold.h"

namespace tp::geometry {
namespace {

using internal::JsonPath;
using internal::member;
using nlohmann::json;

/// Largest quantity of one pattern piece (a cutting ticket, not a production run).
constexpr long long kMaxQuantity = 1000;

/// Keys each object may carry; anything else is reported as a warning (likely a typo).
void warn_unknown_keys(const json& obj, const JsonPath& at, std::initializer_list<const char*> known,
                       std::vector<std::string>& warnings) {
  if (!obj.is_object()) return;
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) warnings.push_back(at.file + ": " + (at / it.key()).pointer + ": unknown key ignored");
  }
}

Result<std::string> optional_string(const json& obj, const char* key, const JsonPath& at, std::string fallback = "") {
  const json* v = member(obj, key);
  if (!v) return fallback;
  return internal::get_string(*v, at / key);
}

Result<double> unit_scale(const json& root, const JsonPath& at) {
  const json* u = member(root, "units");
  if (!u) return 1.0;
  TP_TRY(name, internal::get_string(*u, at / "units"));
  if (name == "mm") return 1.0;
  if (name == "cm") return 10.0;
  if (name == "m") return 1000.0;
  if (name == "in") return 25.4;
  return std::unexpected((at / "units").error(ErrorCode::kParse, "unknown unit '" + name + "' (mm, cm, m or in)"));
}

Result<std::vector<Vec2>> point_list(const json& v, const JsonPath& at, double scale) {
  TP_CHECK(internal::expect_array(v, at));
  std::vector<Vec2> pts;
  for (size_t i = 0; i < v.size(); ++i) {
    TP_TRY(p, internal::get_point(v[i], at / i, scale));
    pts.push_back(p);
  }
  return pts;
}

Result<EdgeCurve> curve_kind(const std::string& s, const JsonPath& at) {
  if (s == "line") return EdgeCurve::kLine;
  if (s == "quadratic") return EdgeCurve::kQuadratic;
  if (s == "cubic") return EdgeCurve::kCubic;
  if (s == "arc") return EdgeCurve::kArc;
  if (s == "polyline") return EdgeCurve::kPolyline;
  return std::unexpected(at.error(ErrorCode::kParse, "unknown curve '" + s + "' (line, quadratic, cubic, arc, polyline)"));
}

Result<NotchType> notch_kind(const std::string& s, const JsonPath& at) {
  if (s == "slit") return NotchType::kSlit;
  if (s == "v") return NotchType::kV;
  if (s == "t") return NotchType::kT;
  if (s == "u") return NotchType::kU;
  return std::unexpected(at.error(ErrorCode::kParse, "unknown notch type '" + s + "' (slit, v, t, u)"));
}

Result<int> edge_by_name(const Piece& piece, const json& v, const JsonPath& at) {
  TP_TRY(name, internal::get_string(v, at));
  int e = find_edge(piece, name);
  if (e < 0) return std::unexpected(at.error(ErrorCode::kUnknownReference, "piece '" + piece.name + "' has no edge '" + name + "'"));
  return e;
}

/// Edges of one piece: each starts at its "from" and ends at the next edge's "from".
Status read_edges(const json& jp, const JsonPath& at, double scale, const PatternImportOptions& opt, Piece& piece,
                  std::vector<std::string>& warnings) {
  const json* je = member(jp, "edges");
  if (!je) return std::unexpected(at.error(ErrorCode::kParse, "piece '" + piece.name + "' has no \"edges\""));
  JsonPath eat = at / "edges";
  TP_CHECK(internal::expect_array(*je, eat));
  if (je->size() < 2) return std::unexpected(eat.error(ErrorCode::kParse, "an outline needs at least 2 edges"));
  std::vector<Vec2> from(je->size());
  for (size_t i = 0; i < je->size(); ++i) {
    const json& e = (*je)[i];
    JsonPath ei = eat / i;
    TP_CHECK(internal::expect_object(e, ei));
    warn_unknown_keys(e, ei, {"name", "from", "curve", "controls", "through", "points"}, warnings);
    const json* f = member(e, "from");
    if (!f) return std::unexpected(ei.error(ErrorCode::kParse, "edge has no \"from\" point"));
    TP_TRY(p, internal::get_point(*f, ei / "from", scale));
    from[i] = p;
    Edge edge;
    TP_TRY(name, optional_string(e, "name", ei, "e" + std::to_string(i)));
    edge.name = name;
    TP_TRY(kind_name, optional_string(e, "curve", ei, "line"));
    TP_TRY(kind, curve_kind(kind_name, ei / "curve"));
    edge.curve = kind;
    switch (kind) {
      case EdgeCurve::kLine:
        break;
      case EdgeCurve::kQuadratic:
      case EdgeCurve::kCubic: {
        const json* c = member(e, "controls");
        if (!c) return std::unexpected(ei.error(ErrorCode::kParse, "a " + kind_name + " edge needs \"controls\""));
        TP_TRY(cps, point_list(*c, ei / "controls", scale));
        size_t per = kind == EdgeCurve::kQuadratic ? 2 : 3;
        if (cps.size() % per != per - 1)
          return std::unexpected((ei / "controls").error(ErrorCode::kParse,
                                                         "a " + kind_name + " chain needs " + (per == 2 ? "2n-1" : "3n-1") +
                                                             " points, found " + std::to_string(cps.size())));
        edge.control_mm = std::move(cps);
        break;
      }
      case EdgeCurve::kArc: {
        const json* t = member(e, "through");
        if (!t) return std::unexpected(ei.error(ErrorCode::kParse, "an arc edge needs a \"through\" point"));
        TP_TRY(tp, internal::get_point(*t, ei / "through", scale));
        edge.control_mm = {Vec2{}, tp};
        break;
      }
      case EdgeCurve::kPolyline: {
        const json* ps = member(e, "points");
        if (!ps) return std::unexpected(ei.error(ErrorCode::kParse, "a polyline edge needs \"points\" (may be empty)"));
        TP_TRY(pts, point_list(*ps, ei / "points", scale));
        edge.points_mm.push_back(Vec2{});
        edge.points_mm.insert(edge.points_mm.end(), pts.begin(), pts.end());
        edge.points_mm.push_back(Vec2{});
        break;
      }
    }
    piece.edges.push_back(std::move(edge));
  }
  for (size_t i = 0; i < piece.edges.size(); ++i) {
    Status s = flatten_edge(piece.edges[i], from[i], from[(i + 1) % from.size()], opt.chord_tolerance_mm);
    if (!s) return std::unexpected(Error{s.error().code, (eat / i).file + ": " + (eat / i).pointer + ": piece '" +
                                                             piece.name + "': " + s.error().message});
  }
  return {};
}

Status read_features(const json& jp, const JsonPath& at, double scale, Piece& piece) {
  if (const json* v = member(jp, "notches")) {
    TP_CHECK(internal::expect_array(*v, at / "notches"));
    for (size_t i = 0; i < v->size(); ++i) {
      const json& n = (*v)[i];
      JsonPath ni = at / "notches" / i;
      TP_CHECK(internal::expect_object(n, ni));
      Notch notch;
      TP_TRY(name, optional_string(n, "name", ni));
      notch.name = name;
      const json* e = member(n, "edge");
      if (!e) return std::unexpected(ni.error(ErrorCode::kParse, "notch has no \"edge\""));
      TP_TRY(edge, edge_by_name(piece, *e, ni / "edge"));
      notch.edge = edge;
      const json* a = member(n, "at");
      if (!a) return std::unexpected(ni.error(ErrorCode::kParse, "notch has no \"at\" (distance along its edge)"));
      TP_TRY(pos, internal::get_number(*a, ni / "at"));
      notch.position_mm = pos * scale;
      TP_TRY(type_name, optional_string(n, "type", ni, "slit"));
      TP_TRY(type, notch_kind(type_name, ni / "type"));
      notch.type = type;
      piece.notches.push_back(notch);
    }
  }
  if (const json* v = member(jp, "grain")) {
    TP_TRY(pts, point_list(*v, at / "grain", scale));
    if (pts.size() != 2) return std::unexpected((at / "grain").error(ErrorCode::kParse, "grain is [from, to]"));
    piece.grain = GrainLine{pts[0], pts[1]};
  }
  if (const json* v = member(jp, "fold_line")) {
    TP_TRY(pts, point_list(*v, at / "fold_line", scale));
    if (pts.size() != 2) return std::unexpected((at / "fold_line").error(ErrorCode::kParse, "fold_line is [from, to]"));
    piece.fold_line_mm = std::array<Vec2, 2>{pts[0], pts[1]};
  }
  if (const json* v = member(jp, "internal_lines")) {
    TP_CHECK(internal::expect_array(*v, at / "internal_lines"));
    for (size_t i = 0; i < v->size(); ++i) {
      JsonPath li = at / "internal_lines" / i;
      TP_CHECK(internal::expect_object((*v)[i], li));
      TP_TRY(name, optional_string((*v)[i], "name", li, "line" + std::to_string(i)));
      const json* ps = member((*v)[i], "points");
      if (!ps) return std::unexpected(li.error(ErrorCode::kParse, "internal line has no \"points\""));
      TP_TRY(pts, point_list(*ps, li / "points", scale));
      if (pts.size() < 2) return std::unexpected((li / "points").error(ErrorCode::kParse, "a line needs 2 or more points"));
      piece.internal_lines.push_back(InternalLine{name, pts});
    }
  }
  if (const json* v = member(jp, "darts")) {
    TP_CHECK(internal::expect_array(*v, at / "darts"));
    for (size_t i = 0; i < v->size(); ++i) {
      JsonPath di = at / "darts" / i;
      TP_CHECK(internal::expect_object((*v)[i], di));
      TP_TRY(name, optional_string((*v)[i], "name", di, "dart" + std::to_string(i)));
      const json* legs = member((*v)[i], "legs");
      if (!legs || !legs->is_array() || legs->size() != 2)
        return std::unexpected(di.error(ErrorCode::kParse, "dart needs \"legs\": [edge, edge]"));
      TP_TRY(a, edge_by_name(piece, (*legs)[0], di / "legs" / 0));
      TP_TRY(b, edge_by_name(piece, (*legs)[1], di / "legs" / 1));
      piece.darts.push_back(Dart{name, a, b});
    }
  }
  if (const json* v = member(jp, "drill_holes")) {
    TP_CHECK(internal::expect_array(*v, at / "drill_holes"));
    for (size_t i = 0; i < v->size(); ++i) {
      JsonPath hi = at / "drill_holes" / i;
      TP_CHECK(internal::expect_object((*v)[i], hi));
      const json* a = member((*v)[i], "at");
      if (!a) return std::unexpected(hi.error(ErrorCode::kParse, "drill hole has no \"at\" point"));
      TP_TRY(p, internal::get_point(*a, hi / "at", scale));
      DrillHole h{p, 3};
      if (const json* d = member((*v)[i], "diameter")) {
        TP_TRY(dia, internal::get_number(*d, hi / "diameter"));
        if (dia < 0) return std::unexpected((hi / "diameter").error(ErrorCode::kParse, "diameter is negative"));
        h.diameter_mm = dia * scale;
      }
      piece.drill_holes.push_back(h);
    }
  }
  if (const json* v = member(jp, "placement")) {
    JsonPath pa = at / "placement";
    TP_CHECK(internal::expect_object(*v, pa));
    Placement3d pl;
    if (const json* t = member(*v, "translation")) {
      if (!t->is_array() || t->size() != 3)
        return std::unexpected((pa / "translation").error(ErrorCode::kParse, "translation is [x, y, z]"));
      double xyz[3];
      for (size_t k = 0; k < 3; ++k) {
        TP_TRY(c, internal::get_number((*t)[k], pa / "translation" / k));
        xyz[k] = c * scale;
      }
      pl.translation_mm = Vec3{xyz[0], xyz[1], xyz[2]};
    }
    const json* rd = member(*v, "rotation_deg");
    const json* rm = member(*v, "rotation");
    if (rd && rm) return std::unexpected(pa.error(ErrorCode::kParse, "give either rotation_deg or rotation, not both"));
    if (rd) {
      if (!rd->is_array() || rd->size() != 3)
        return std::unexpected((pa / "rotation_deg").error(ErrorCode::kParse, "rotation_deg is [rx, ry, rz]"));
      double a[3];
      for (size_t k = 0; k < 3; ++k) {
        TP_TRY(c, internal::get_number((*rd)[k], pa / "rotation_deg" / k));
        a[k] = c;
      }
      pl.rotation = rotation_from_euler_xyz_deg(a[0], a[1], a[2]);
    } else if (rm) {
      if (!rm->is_array() || rm->size() != 9)
        return std::unexpected((pa / "rotation").error(ErrorCode::kParse, "rotation is a row-major 3x3 matrix (9 numbers)"));
      for (size_t k = 0; k < 9; ++k) {
        TP_TRY(c, internal::get_number((*rm)[k], pa / "rotation" / k));
        pl.rotation[k] = c;
      }
    }
    piece.placement = pl;
  }
  return {};
}

struct Drafted {
  Piece piece;
  int quantity = 1;
  bool mirror_pairs = false;
  DraftedSide side = DraftedSide::kLeft;
};

Result<Drafted> read_piece(const json& jp, const JsonPath& at, double scale, const PatternImportOptions& opt,
                           std::vector<std::string>& warnings) {
  TP_CHECK(internal::expect_object(jp, at));
  warn_unknown_keys(jp, at,
                    {"name", "role", "material", "quantity", "mirror_pairs", "drafted_side", "source_piece", "mirrored",
                     "edges", "fold", "fold_line", "notches", "grain", "internal_lines", "darts", "drill_holes",
                     "placement"},
                    warnings);
  Drafted d;
  const json* n = member(jp, "name");
  if (!n) return std::unexpected(at.error(ErrorCode::kParse, "piece has no \"name\""));
  TP_TRY(name, internal::get_string(*n, at / "name"));
  if (name.empty()) return std::unexpected((at / "name").error(ErrorCode::kParse, "piece name is empty"));
  d.piece.name = name;
  TP_TRY(role, optional_string(jp, "role", at));
  TP_TRY(material, optional_string(jp, "material", at));
  TP_TRY(source, optional_string(jp, "source_piece", at));
  d.piece.role = role;
  d.piece.material = material;
  d.piece.source_piece = source;
  if (const json* m = member(jp, "mirrored")) {
    TP_TRY(b, internal::get_bool(*m, at / "mirrored"));
    d.piece.mirrored = b;
  }
  if (const json* q = member(jp, "quantity")) {
    TP_TRY(qty, internal::get_integer(*q, at / "quantity", 1, kMaxQuantity));
    d.quantity = static_cast<int>(qty);
  }
  if (const json* m = member(jp, "mirror_pairs")) {
    TP_TRY(b, internal::get_bool(*m, at / "mirror_pairs"));
    d.mirror_pairs = b;
  }
  if (d.mirror_pairs && d.quantity % 2 != 0)
    return std::unexpected((at / "quantity").error(ErrorCode::kParse, "mirror_pairs needs an even quantity, found " +
                                                                          std::to_string(d.quantity)));
  TP_TRY(side, optional_string(jp, "drafted_side", at, opt.drafted_side == DraftedSide::kLeft ? "left" : "right"));
  if (side != "left" && side != "right")
    return std::unexpected((at / "drafted_side").error(ErrorCode::kParse, "drafted_side is \"left\" or \"right\""));
  d.side = side == "left" ? DraftedSide::kLeft : DraftedSide::kRight;
  TP_CHECK(read_edges(jp, at, scale, opt, d.piece, warnings));
  TP_CHECK(read_features(jp, at, scale, d.piece));
  if (const json* f = member(jp, "fold")) {
    TP_TRY(fe, edge_by_name(d.piece, *f, at / "fold"));
    d.piece.fold_edge = fe;
  }
  return d;
}

}  // namespace

Result<Pattern> read_pattern_json(std::string_view text, const std::string& source_name,
                                  const PatternImportOptions& options) {
  TP_TRY(root, internal::parse_json(text, source_name));
  JsonPath at{source_name, ""};
  TP_CHECK(internal::expect_object(root, at));
  Pattern pattern;
  warn_unknown_keys(root, at, {"format", "version", "name", "size", "units", "pieces", "stitches"}, pattern.warnings);
  if (const json* f = member(root, "format")) {
    TP_TRY(fmt, internal::get_string(*f, at / "format"));
    if (fmt != "tp-pattern")
      return std::unexpected((at / "format").error(ErrorCode::kParse, "format is '" + fmt + "', expected 'tp-pattern'"));
  }
  if (const json* v = member(root, "version")) {
    TP_TRY(ver, internal::get_integer(*v, at / "version", 1, 1000));
    if (ver != 1)
      return std::unexpected((at / "version").error(ErrorCode::kParse, "version " + std::to_string(ver) + " is not supported (1)"));
  }
  TP_TRY(scale, unit_scale(root, at));
  TP_TRY(name, optional_string(root, "name", at));
  TP_TRY(size, optional_string(root, "size", at));
  pattern.name = name;
  pattern.size = size;
  const json* jp = member(root, "pieces");
  if (!jp) return std::unexpected(at.error(ErrorCode::kParse, "no \"pieces\""));
  TP_CHECK(internal::expect_array(*jp, at / "pieces"));

  // Drafted pieces become physical ones: unfolded, then expanded into copies.
  std::map<std::string, bool> unfolded;
  std::set<std::string> drafted_names;
  for (size_t i = 0; i < jp->size(); ++i) {
    JsonPath pi = at / "pieces" / i;
    TP_TRY(d, read_piece((*jp)[i], pi, scale, options, pattern.warnings));
    if (!drafted_names.insert(d.piece.name).second)
      return std::unexpected((pi / "name").error(ErrorCode::kParse, "duplicate piece name '" + d.piece.name + "'"));
    Piece piece = std::move(d.piece);
    bool was_unfolded = false;
    if (piece.fold_edge && options.unfold_cut_on_fold) {
      auto whole = unfold_piece(piece, *piece.fold_edge);
      if (!whole) return std::unexpected(whole.error().with_context(pi.file + ": " + (pi / "fold").pointer));
      piece = std::move(*whole);
      was_unfolded = true;
    }
    int qty = options.expand_quantity ? d.quantity : 1;
    for (Piece& p : expand_copies(piece, qty, d.mirror_pairs, d.side)) {
      unfolded[p.name] = was_unfolded;
      pattern.pieces.push_back(std::move(p));
    }
  }
  std::set<std::string> physical;
  for (const Piece& p : pattern.pieces)
    if (!physical.insert(p.name).second)
      return std::unexpected(at.error(ErrorCode::kParse, "two physical pieces are named '" + p.name +
                                                             "' (a copy's name collides with another piece)"));
  TP_CHECK(internal::read_pattern_json_stitches(root, at, scale, unfolded, pattern));
  if (options.fix_orientation)
    for (const std::string& n : orient_counter_clockwise(pattern))
      pattern.warnings.push_back(source_name + ": piece '" + n + "': outline was clockwise; reversed");
  return pattern;
}

Result<Pattern> load_pattern_json(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_pattern_json(text, path.string(), options);
}

}  // namespace tp::geometry
