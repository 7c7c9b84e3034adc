// geometry/pattern/internal/pattern_json_stitches.cpp: resolving native-format stitches to physical pieces.
#include "geometry/pattern/internal/pattern_json_stitches.h"

#include "geometry/pattern/internal/try.h"

namespace tp::geometry::internal {
namespace {

using nlohmann::json;

/// One physical edge a stitch side names; `twin` marks the mirrored half of an unfolded piece,
/// whose positions are measured from the other end.
struct Instance {
  int piece = 0;
  int edge = 0;     ///< the edge the span lies on
  int source = 0;   ///< the edge names and numbers refer to (== edge unless twin)
  bool twin = false;
};

Result<std::vector<Instance>> instances(const json& side, const JsonPath& at, const std::map<std::string, bool>& unfolded,
                                        const Pattern& pattern) {
  TP_CHECK(expect_object(side, at));
  const json* jp = member(side, "piece");
  const json* je = member(side, "edge");
  if (!jp || !je) return std::unexpected(at.error(ErrorCode::kParse, "a stitch side needs \"piece\" and \"edge\""));
  TP_TRY(pname, get_string(*jp, at / "piece"));
  TP_TRY(ename, get_string(*je, at / "edge"));
  std::vector<int> pieces;
  int exact = find_piece(pattern, pname);
  if (exact >= 0) {
    pieces.push_back(exact);
  } else {
    // A drafted piece's name stands for all its copies, in the order they were cut.
    for (size_t i = 0; i < pattern.pieces.size(); ++i)
      if (pattern.pieces[i].source_piece == pname) pieces.push_back(static_cast<int>(i));
  }
  if (pieces.empty()) return std::unexpected((at / "piece").error(ErrorCode::kUnknownReference, "no piece named '" + pname + "'"));
  std::vector<Instance> out;
  for (int p : pieces) {
    const Piece& piece = pattern.pieces[p];
    const std::string suffix = "_mirror";
    bool is_mirror = ename.size() > suffix.size() && ename.compare(ename.size() - suffix.size(), suffix.size(), suffix) == 0;
    int e = find_edge(piece, ename);
    // A half kept folded stands for both halves: "x_mirror" is its edge "x".
    if (e < 0 && is_mirror && piece.fold_edge) e = find_edge(piece, ename.substr(0, ename.size() - suffix.size()));
    if (e < 0)
      return std::unexpected((at / "edge").error(ErrorCode::kUnknownReference, "piece '" + piece.name + "' has no edge '" + ename + "'"));
    out.push_back(Instance{p, e, e, false});
    // On an unfolded piece the stitch also holds for the mirrored half: "x" <-> "x_mirror".
    auto it = unfolded.find(piece.name);
    if (it != unfolded.end() && it->second) {
      int twin = find_edge(piece, is_mirror ? ename.substr(0, ename.size() - suffix.size()) : ename + suffix);
      if (twin >= 0) out.push_back(Instance{p, twin, e, true});
    }
  }
  return out;
}

/// A span end on the source edge, in mm: a number (file units), "start", "end" or a notch name.
Result<double> position(const json* v, const JsonPath& at, double scale, const Piece& piece, int edge, double fallback) {
  if (!v) return fallback;
  double len = edge_length_mm(piece.edges[edge]);
  if (v->is_number()) {
    TP_TRY(x, get_number(*v, at));
    return x * scale;
  }
  TP_TRY(name, get_string(*v, at));
  if (name == "start") return 0.0;
  if (name == "end") return len;
  for (const Notch& n : piece.notches)
    if (n.edge == edge && n.name == name) return n.position_mm;
  return std::unexpected(at.error(ErrorCode::kUnknownReference, "edge '" + piece.edges[edge].name + "' of piece '" +
                                                                    piece.name + "' has no notch '" + name + "'"));
}

Result<EdgeSpan> span_of(const json& side, const JsonPath& at, double scale, const Instance& inst, const Pattern& pattern) {
  const Piece& piece = pattern.pieces[inst.piece];
  double len = edge_length_mm(piece.edges[inst.source]);
  TP_TRY(from, position(member(side, "from"), at / "from", scale, piece, inst.source, 0.0));
  TP_TRY(to, position(member(side, "to"), at / "to", scale, piece, inst.source, len));
  EdgeSpan s{inst.piece, inst.edge, from, to};
  // The twin runs the other way: [from, to] on the source is [len - to, len - from] on it.
  if (inst.twin) s = EdgeSpan{inst.piece, inst.edge, len - to, len - from};
  if (s.from_mm <= 0) s.from_mm = 0;
  if (s.to_mm >= len) s.to_mm = -1;
  return s;
}

}  // namespace

Status read_pattern_json_stitches(const json& root, const JsonPath& at, double scale,
                                  const std::map<std::string, bool>& unfolded, Pattern& pattern) {
  const json* js = member(root, "stitches");
  if (!js) return {};
  JsonPath sat = at / "stitches";
  TP_CHECK(expect_array(*js, sat));
  for (size_t i = 0; i < js->size(); ++i) {
    const json& s = (*js)[i];
    JsonPath si = sat / i;
    TP_CHECK(expect_object(s, si));
    const json* a = member(s, "a");
    const json* b = member(s, "b");
    if (!a || !b) return std::unexpected(si.error(ErrorCode::kParse, "a stitch needs sides \"a\" and \"b\""));
    bool same = false;
    if (const json* v = member(s, "same_direction")) {
      TP_TRY(flag, get_bool(*v, si / "same_direction"));
      same = flag;
    }
    double ease = 0;
    if (const json* v = member(s, "ease")) {
      TP_TRY(r, get_number(*v, si / "ease"));
      if (!(r >= 1 && r <= 4))
        return std::unexpected((si / "ease").error(ErrorCode::kInvalidPattern, "ease ratio must be in [1, 4]"));
      ease = r;
    }
    TP_TRY(ia, instances(*a, si / "a", unfolded, pattern));
    TP_TRY(ib, instances(*b, si / "b", unfolded, pattern));
    if (ia.size() != ib.size())
      return std::unexpected(si.error(ErrorCode::kUnknownReference,
                                      "side a names " + std::to_string(ia.size()) + " physical edges and side b " +
                                          std::to_string(ib.size()) + "; name physical pieces (e.g. 'sleeve_l') to pair them"));
    for (size_t k = 0; k < ia.size(); ++k) {
      TP_TRY(sa, span_of(*a, si / "a", scale, ia[k], pattern));
      TP_TRY(sb, span_of(*b, si / "b", scale, ib[k], pattern));
      pattern.stitches.push_back(Stitch{sa, sb, same, ease});
    }
  }
  return {};
}

}  // namespace tp::geometry::internal
