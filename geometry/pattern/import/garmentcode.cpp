// geometry/pattern/garmentcode.cpp: GarmentCode specification JSON to the pattern model.
#include "geometry/pattern/import/garmentcode.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "geometry/pattern/internal/json_fields.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/text.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/orient.h"
#include "geometry/pattern/placement.h"
#include "geometry/pattern/role.h"
#include "geometry/pattern/validate.h"

namespace tp::geometry {
namespace {

using internal::JsonPath;
using internal::member;
using nlohmann::json;

/// A circle radius may fall short of half its chord by this fraction (rounding in the file)
/// before the arc is impossible; GarmentCode itself tolerates 1e-3 on the squared values.
constexpr double kCircleRadiusSlack = 1e-3;
/// Most vertices or edges a panel may have; real panels have tens.
constexpr size_t kMaxPanelEdges = 100000;

struct Settings {
  double scale = 10;       ///< mm per file unit
  bool relative = true;    ///< curvature control points relative to their edge
};

Result<Settings> read_settings(const json& root, const JsonPath& at) {
  Settings s;
  const json* props = member(root, "properties");
  if (!props) return s;
  JsonPath pa = at / "properties";
  TP_CHECK(internal::expect_object(*props, pa));
  if (const json* u = member(*props, "units_in_meter")) {
    TP_TRY(per_m, internal::get_number(*u, pa / "units_in_meter"));
    if (!(per_m > 0)) return std::unexpected((pa / "units_in_meter").error(ErrorCode::kParse, "must be positive"));
    s.scale = 1000.0 / per_m;
  }
  if (const json* c = member(*props, "curvature_coords")) {
    TP_TRY(mode, internal::get_string(*c, pa / "curvature_coords"));
    if (mode != "relative" && mode != "absolute")
      return std::unexpected((pa / "curvature_coords").error(ErrorCode::kParse, "is '" + mode + "', expected relative or absolute"));
    s.relative = mode == "relative";
  }
  return s;
}

/// A control point of a Bezier edge from its [t, s] (relative) or [x, y] (absolute) form.
Result<Vec2> control_point(const json& v, const JsonPath& at, Vec2 a, Vec2 b, const Settings& st) {
  TP_TRY(p, internal::get_point(v, at));
  if (!st.relative) return p * st.scale;
  Vec2 d = b - a;
  return a + d * p.x + perp(d) * p.y;
}

/// The point halfway along a circle arc from a to b, from GarmentCode's [radius, large_arc, right].
Result<Vec2> arc_midpoint(const json& params, const JsonPath& at, Vec2 a, Vec2 b, const Settings& st) {
  if (!params.is_array() || params.size() != 3)
    return std::unexpected(at.error(ErrorCode::kParse, "circle params are [radius, large_arc, right]"));
  TP_TRY(radius, internal::get_number(params[0], at / 0));
  TP_TRY(large, internal::get_bool(params[1], at / 1));
  TP_TRY(right, internal::get_bool(params[2], at / 2));
  double r = radius * st.scale;
  double chord = norm(b - a);
  if (!(chord > 0)) return std::unexpected(at.error(ErrorCode::kInvalidPattern, "circle edge has coincident ends"));
  double half = chord / 2;
  if (!(r >= half * (1 - kCircleRadiusSlack)))
    return std::unexpected(at.error(ErrorCode::kInvalidPattern, "circle radius " + internal::mm(r) +
                                                                    " mm is shorter than half its chord (" +
                                                                    internal::mm(half) + " mm)"));
  double h = r > half ? std::sqrt(r * r - half * half) : 0;
  double sagitta = large ? r + h : r - h;
  // "right" puts the arc on the right of the direction of travel (GarmentCode's control_y < 0).
  Vec2 n = perp(b - a) / chord * (right ? -1.0 : 1.0);
  return (a + b) * 0.5 + n * sagitta;
}

Result<Edge> read_edge(const json& je, const JsonPath& at, const std::vector<Vec2>& verts, int index, int expected_start,
                       const Settings& st, const PatternImportOptions& opt, int& start_vertex, int& end_vertex) {
  TP_CHECK(internal::expect_object(je, at));
  const json* ends = member(je, "endpoints");
  if (!ends || !ends->is_array() || ends->size() != 2)
    return std::unexpected(at.error(ErrorCode::kParse, "edge needs \"endpoints\": [from, to]"));
  long long n = static_cast<long long>(verts.size()) - 1;
  TP_TRY(i0, internal::get_integer((*ends)[0], at / "endpoints" / 0, 0, n));
  TP_TRY(i1, internal::get_integer((*ends)[1], at / "endpoints" / 1, 0, n));
  if (expected_start >= 0 && i0 != expected_start)
    return std::unexpected((at / "endpoints").error(ErrorCode::kParse, "edge starts at vertex " + std::to_string(i0) +
                                                                           " but the previous edge ends at vertex " +
                                                                           std::to_string(expected_start)));
  start_vertex = static_cast<int>(i0);
  end_vertex = static_cast<int>(i1);
  Vec2 a = verts[i0], b = verts[i1];
  Edge e;
  e.name = "e" + std::to_string(index);
  const json* curv = member(je, "curvature");
  if (curv && curv->is_array()) {
    // The older form: "curvature": [t, s] is a quadratic's relative control point.
    TP_TRY(c, control_point(*curv, at / "curvature", a, b, st));
    e.curve = EdgeCurve::kQuadratic;
    e.control_mm = {c};
  } else if (curv) {
    JsonPath ca = at / "curvature";
    TP_CHECK(internal::expect_object(*curv, ca));
    const json* type = member(*curv, "type");
    const json* params = member(*curv, "params");
    if (!type || !params) return std::unexpected(ca.error(ErrorCode::kParse, "curvature needs \"type\" and \"params\""));
    TP_TRY(kind, internal::get_string(*type, ca / "type"));
    if (kind == "quadratic" || kind == "cubic") {
      size_t want = kind == "quadratic" ? 1 : 2;
      if (!params->is_array() || params->size() != want)
        return std::unexpected((ca / "params").error(ErrorCode::kParse, "a " + kind + " edge has " + std::to_string(want) +
                                                                           " control point(s)"));
      e.curve = kind == "quadratic" ? EdgeCurve::kQuadratic : EdgeCurve::kCubic;
      for (size_t k = 0; k < want; ++k) {
        TP_TRY(c, control_point((*params)[k], ca / "params" / k, a, b, st));
        e.control_mm.push_back(c);
      }
    } else if (kind == "circle") {
      TP_TRY(mid, arc_midpoint(*params, ca / "params", a, b, st));
      e.curve = EdgeCurve::kArc;
      e.control_mm = {Vec2{}, mid};
    } else {
      return std::unexpected((ca / "type").error(ErrorCode::kParse, "unknown curvature '" + kind + "' (quadratic, cubic, circle)"));
    }
  }
  Status s = flatten_edge(e, a, b, opt.chord_tolerance_mm);
  if (!s) return std::unexpected(at.error(s.error().code, s.error().message));
  return e;
}

Result<Piece> read_panel(const std::string& name, const json& jp, const JsonPath& at, const Settings& st,
                         const PatternImportOptions& opt) {
  TP_CHECK(internal::expect_object(jp, at));
  Piece piece;
  piece.name = name;
  const json* jv = member(jp, "vertices");
  const json* je = member(jp, "edges");
  if (!jv || !je) return std::unexpected(at.error(ErrorCode::kParse, "panel needs \"vertices\" and \"edges\""));
  TP_CHECK(internal::expect_array(*jv, at / "vertices"));
  TP_CHECK(internal::expect_array(*je, at / "edges"));
  if (jv->size() > kMaxPanelEdges || je->size() > kMaxPanelEdges)
    return std::unexpected(at.error(ErrorCode::kParse, "panel has more than " + std::to_string(kMaxPanelEdges) + " vertices or edges"));
  if (je->size() < 2) return std::unexpected((at / "edges").error(ErrorCode::kParse, "a panel needs at least 2 edges"));
  std::vector<Vec2> verts;
  for (size_t i = 0; i < jv->size(); ++i) {
    TP_TRY(v, internal::get_point((*jv)[i], at / "vertices" / i, st.scale));
    verts.push_back(v);
  }
  if (verts.empty()) return std::unexpected((at / "vertices").error(ErrorCode::kParse, "panel has no vertices"));
  int expected = -1, first = -1;
  for (size_t i = 0; i < je->size(); ++i) {
    int start = 0, end = 0;
    TP_TRY(e, read_edge((*je)[i], at / "edges" / i, verts, static_cast<int>(i), expected, st, opt, start, end));
    if (i == 0) first = start;
    expected = end;
    piece.edges.push_back(std::move(e));
  }
  if (expected != first)
    return std::unexpected((at / "edges").error(ErrorCode::kParse, "edge loop does not close: the last edge ends at vertex " +
                                                                       std::to_string(expected) + ", the first starts at " +
                                                                       std::to_string(first)));
  Placement3d pl;
  if (const json* t = member(jp, "translation")) {
    if (!t->is_array() || t->size() != 3)
      return std::unexpected((at / "translation").error(ErrorCode::kParse, "translation is [x, y, z]"));
    double v[3];
    for (size_t k = 0; k < 3; ++k) {
      TP_TRY(c, internal::get_number((*t)[k], at / "translation" / k));
      v[k] = c * st.scale;
    }
    pl.translation_mm = {v[0], v[1], v[2]};
  }
  if (const json* r = member(jp, "rotation")) {
    if (!r->is_array() || r->size() != 3)
      return std::unexpected((at / "rotation").error(ErrorCode::kParse, "rotation is [rx, ry, rz] in degrees"));
    double a[3];
    for (size_t k = 0; k < 3; ++k) {
      TP_TRY(c, internal::get_number((*r)[k], at / "rotation" / k));
      a[k] = c;
    }
    pl.rotation = rotation_from_euler_xyz_deg(a[0], a[1], a[2]);
  }
  // GarmentCode draws every panel as seen from the +z side of its own frame, so panels facing
  // away from it (backs) are stored mirror-imaged, clockwise. The pattern wants each piece right
  // side up: mirror the 2D frame (x -> -x) and turn the placement by 180 degrees about the
  // panel's y axis, which puts every point back at the same 3D position with a proper rotation.
  if (signed_area(outline(piece)) < 0) {
    const Affine2 flip = Affine2::scale(-1, 1);
    for (Edge& e : piece.edges) e = transformed_edge(e, flip);
    for (int row = 0; row < 3; ++row) {
      pl.rotation[row * 3 + 0] = -pl.rotation[row * 3 + 0];
      pl.rotation[row * 3 + 2] = -pl.rotation[row * 3 + 2];
    }
  }
  piece.placement = pl;
  piece.role = guess_role(name);
  if (piece.role.empty())
    if (const json* l = member(jp, "label"); l && l->is_string()) piece.role = l->get<std::string>();
  piece.material = "fabric";
  return piece;
}

Result<EdgeSpan> stitch_side(const json& side, const JsonPath& at, const std::map<std::string, int>& index,
                             const Pattern& pattern) {
  TP_CHECK(internal::expect_object(side, at));
  const json* p = member(side, "panel");
  const json* e = member(side, "edge");
  if (!p || !e) return std::unexpected(at.error(ErrorCode::kParse, "stitch side needs \"panel\" and \"edge\""));
  TP_TRY(panel, internal::get_string(*p, at / "panel"));
  auto it = index.find(panel);
  if (it == index.end()) return std::unexpected((at / "panel").error(ErrorCode::kUnknownReference, "no panel '" + panel + "'"));
  const Piece& piece = pattern.pieces[it->second];
  long long n = static_cast<long long>(piece.edges.size());
  if (!e->is_number_integer() || e->get<long long>() < 0 || e->get<long long>() >= n)
    return std::unexpected((at / "edge").error(ErrorCode::kUnknownReference, "panel '" + panel + "' has edges 0.." +
                                                                                 std::to_string(n - 1) + ", not " + e->dump()));
  return EdgeSpan{it->second, static_cast<int>(e->get<long long>()), 0, -1};
}

}  // namespace

Result<Pattern> read_garmentcode(std::string_view text, const std::string& source_name, const PatternImportOptions& options) {
  TP_TRY(root, internal::parse_json(text, source_name));
  JsonPath at{source_name, ""};
  TP_CHECK(internal::expect_object(root, at));
  TP_TRY(st, read_settings(root, at));
  const json* jpat = member(root, "pattern");
  if (!jpat) return std::unexpected(at.error(ErrorCode::kParse, "no \"pattern\" (not a GarmentCode specification?)"));
  JsonPath pa = at / "pattern";
  TP_CHECK(internal::expect_object(*jpat, pa));
  const json* panels = member(*jpat, "panels");
  if (!panels) return std::unexpected(pa.error(ErrorCode::kParse, "no \"panels\""));
  TP_CHECK(internal::expect_object(*panels, pa / "panels"));

  // Panel order: as the file lists it in panel_order (GarmentCode's own order), else by name.
  std::vector<std::string> order;
  if (const json* po = member(*jpat, "panel_order")) {
    TP_CHECK(internal::expect_array(*po, pa / "panel_order"));
    std::set<std::string> seen;
    for (size_t i = 0; i < po->size(); ++i) {
      TP_TRY(n, internal::get_string((*po)[i], pa / "panel_order" / i));
      if (!member(*panels, n))
        return std::unexpected((pa / "panel_order" / i).error(ErrorCode::kUnknownReference, "no panel '" + n + "'"));
      if (seen.insert(n).second) order.push_back(n);
    }
  }
  for (auto it = panels->begin(); it != panels->end(); ++it)
    if (std::find(order.begin(), order.end(), it.key()) == order.end()) order.push_back(it.key());

  Pattern pattern;
  pattern.name = std::filesystem::path(source_name).stem().string();
  std::map<std::string, int> index;
  for (const std::string& name : order) {
    TP_TRY(piece, read_panel(name, (*panels)[name], pa / "panels" / name, st, options));
    index[name] = static_cast<int>(pattern.pieces.size());
    pattern.pieces.push_back(std::move(piece));
  }

  if (const json* js = member(*jpat, "stitches")) {
    JsonPath sa = pa / "stitches";
    TP_CHECK(internal::expect_array(*js, sa));
    for (size_t i = 0; i < js->size(); ++i) {
      const json& s = (*js)[i];
      JsonPath si = sa / i;
      if (!s.is_array() || s.size() < 2)
        return std::unexpected(si.error(ErrorCode::kParse, "a stitch is [{panel, edge}, {panel, edge}, optional \"right_wrong\"]"));
      TP_TRY(a, stitch_side(s[0], si / 0, index, pattern));
      TP_TRY(b, stitch_side(s[1], si / 1, index, pattern));
      bool right_wrong = false;
      for (size_t k = 2; k < s.size(); ++k) right_wrong = right_wrong || (s[k].is_string() && s[k] == "right_wrong");
      pattern.stitches.push_back(Stitch{a, b, right_wrong});
    }
  }
  // GarmentCode gathers by design (its `ruffle` lengthens one side of a stitch): a stitch whose
  // sides differ beyond the validator's tolerance is marked gathered with its ratio, so it is
  // sewn with the longer side distributed along the shorter, not refused.
  for (Stitch& st : pattern.stitches)
    if (const double r = mismatch_ease_ratio(pattern, st); r > 0) st.ease_ratio = r;
  if (options.fix_orientation)
    for (const std::string& n : orient_counter_clockwise(pattern))
      pattern.warnings.push_back(source_name + ": panel '" + n + "': outline was clockwise; reversed");
  return pattern;
}

Result<Pattern> load_garmentcode(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_garmentcode(text, path.string(), options);
}

}  // namespace tp::geometry
