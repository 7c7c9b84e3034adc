// tests/geometry/pattern/pattern_json_test.cpp: the native JSON format: the example tee, broken input, round trip.
#include "geometry/pattern/pattern_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "geometry/pattern/validate.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

std::filesystem::path tee_path() { return tp::test::source_dir() / "examples/patterns/tee.json"; }

const Stitch* find_stitch(const Pattern& p, const std::string& pa, const std::string& ea, const std::string& pb,
                          const std::string& eb) {
  for (const Stitch& s : p.stitches) {
    const Piece& a = p.pieces[s.a.piece];
    const Piece& b = p.pieces[s.b.piece];
    if (a.name == pa && a.edges[s.a.edge].name == ea && b.name == pb && b.edges[s.b.edge].name == eb) return &s;
  }
  return nullptr;
}

std::string error_of(const std::string& text) {
  auto r = read_pattern_json(text, "bad.json");
  EXPECT_FALSE(r.has_value());
  return r ? std::string() : r.error().message;
}

TEST(PatternJson, TheGatheredSkirtExampleIsValidWithItsEaseAndNotWithout) {
  auto r = load_pattern_json(tp::test::source_dir() / "examples/patterns/gathered_skirt.json");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  Pattern p = *r;
  // The skirt's tops (570 mm front, 285 mm back halves) gathered into 400 and 200 mm of the band.
  const Stitch* front = find_stitch(p, "skirt_front", "top", "waistband", "bottom");
  ASSERT_NE(front, nullptr);
  EXPECT_DOUBLE_EQ(front->ease_ratio, 1.45);
  EXPECT_TRUE(validate_pattern(p).has_value());
  for (Stitch& s : p.stitches) s.ease_ratio = 0;
  auto unmarked = validate_pattern(p);
  ASSERT_FALSE(unmarked.has_value());
  EXPECT_NE(unmarked.error().message.find("skirt_front"), std::string::npos) << unmarked.error().message;
}

TEST(PatternJson, ReadsTheExampleTeeIntoPhysicalPieces) {
  auto r = load_pattern_json(tee_path());
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Pattern& p = *r;
  EXPECT_EQ(p.name, "tee");
  EXPECT_EQ(p.size, "M");
  // Front and back unfold into whole pieces, the sleeve becomes a left/right pair.
  ASSERT_EQ(p.pieces.size(), 4u);
  EXPECT_EQ(p.pieces[0].name, "front");
  EXPECT_EQ(p.pieces[1].name, "back");
  EXPECT_EQ(p.pieces[2].name, "sleeve_l");
  EXPECT_EQ(p.pieces[3].name, "sleeve_r");
  EXPECT_FALSE(p.pieces[2].mirrored);
  EXPECT_TRUE(p.pieces[3].mirrored);
  EXPECT_EQ(p.pieces[3].source_piece, "sleeve");
  ASSERT_TRUE(p.pieces[0].fold_line_mm.has_value());
  // The unfolded front is 520 mm wide and symmetric about x = 0.
  Box2 box = bounds(outline(p.pieces[0]));
  EXPECT_NEAR(box.min.x, -260, 1e-9);
  EXPECT_NEAR(box.max.x, 260, 1e-9);
  EXPECT_GT(signed_area(outline(p.pieces[0])), 0);
  // Hem and neck cross the fold, so they are single edges; the other four edges come in pairs.
  EXPECT_EQ(p.pieces[0].edges.size(), 8u);
  EXPECT_EQ(find_edge(p.pieces[0], "centre_front"), -1);
  EXPECT_GE(find_edge(p.pieces[0], "side_mirror"), 0);
  EXPECT_NEAR(edge_length_mm(p.pieces[0].edges[find_edge(p.pieces[0], "hem")]), 520, 1e-9);
  // Notches are mirrored with the half.
  EXPECT_EQ(p.pieces[0].notches.size(), 2u);
  // Each stitch written once holds for both sides: 5 written, 10 physical.
  EXPECT_EQ(p.stitches.size(), 10u);
  EXPECT_NE(find_stitch(p, "front", "side", "back", "side_mirror"), nullptr);
  EXPECT_NE(find_stitch(p, "front", "side_mirror", "back", "side"), nullptr);
  EXPECT_NE(find_stitch(p, "front", "armhole", "sleeve_l", "cap_front"), nullptr);
  EXPECT_NE(find_stitch(p, "front", "armhole_mirror", "sleeve_r", "cap_front"), nullptr);
  EXPECT_NE(find_stitch(p, "back", "armhole", "sleeve_r", "cap_back"), nullptr);
  EXPECT_NE(find_stitch(p, "sleeve_r", "underarm_back", "sleeve_r", "underarm_front"), nullptr);
  Status valid = validate_pattern(p);
  EXPECT_TRUE(valid.has_value()) << valid.error().what();
  EXPECT_TRUE(p.warnings.empty());
}

TEST(PatternJson, StitchedEdgesOfTheTeeMeetAtMatchingEnds) {
  auto r = load_pattern_json(tee_path());
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Pattern& p = *r;
  // Sewing is right sides together: a's start meets b's end. Check in piece geometry that the
  // side seam starts at the hem on both pieces' hem corners (same height).
  const Stitch* s = find_stitch(p, "front", "side", "back", "side_mirror");
  ASSERT_NE(s, nullptr);
  const Edge& a = p.pieces[s->a.piece].edges[s->a.edge];
  const Edge& b = p.pieces[s->b.piece].edges[s->b.edge];
  EXPECT_NEAR(a.points_mm.front().y, 0, 1e-9);
  EXPECT_NEAR(b.points_mm.back().y, 0, 1e-9);
  EXPECT_FALSE(s->same_direction);
}

TEST(PatternJson, KeepsHalvesFoldedAndCopiesSingleWhenAsked) {
  PatternImportOptions o;
  o.unfold_cut_on_fold = false;
  o.expand_quantity = false;
  auto r = load_pattern_json(tee_path(), o);
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pieces.size(), 3u);
  ASSERT_TRUE(r->pieces[0].fold_edge.has_value());
  EXPECT_EQ(r->pieces[0].edges[*r->pieces[0].fold_edge].name, "centre_front");
}

TEST(PatternJson, RoundTripIsExactAndStable) {
  auto r = load_pattern_json(tee_path());
  ASSERT_TRUE(r.has_value()) << r.error().what();
  std::string once = write_pattern_json(*r);
  auto again = read_pattern_json(once, "written.json");
  ASSERT_TRUE(again.has_value()) << again.error().what();
  EXPECT_EQ(write_pattern_json(*again), once);
  ASSERT_EQ(again->pieces.size(), r->pieces.size());
  for (size_t i = 0; i < r->pieces.size(); ++i) {
    const Piece& a = r->pieces[i];
    const Piece& b = again->pieces[i];
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t e = 0; e < a.edges.size(); ++e) {
      EXPECT_EQ(a.edges[e].curve, b.edges[e].curve) << a.name << " " << a.edges[e].name;
      ASSERT_EQ(a.edges[e].points_mm.size(), b.edges[e].points_mm.size()) << a.name << " " << a.edges[e].name;
      for (size_t k = 0; k < a.edges[e].points_mm.size(); ++k) EXPECT_EQ(a.edges[e].points_mm[k], b.edges[e].points_mm[k]);
    }
    EXPECT_EQ(a.mirrored, b.mirrored);
    EXPECT_EQ(a.source_piece, b.source_piece);
  }
  EXPECT_EQ(again->stitches.size(), r->stitches.size());
}

TEST(PatternJson, UnitsScaleEveryLength) {
  const std::string cm = R"({"units": "cm", "pieces": [{"name": "sq", "edges": [
      {"name": "a", "from": [0, 0]}, {"name": "b", "from": [10, 0]}, {"name": "c", "from": [10, 10]},
      {"name": "d", "from": [0, 10]}],
      "notches": [{"edge": "a", "at": 5}],
      "placement": {"translation": [1, 2, 3], "rotation_deg": [0, 90, 0]}}]})";
  auto r = read_pattern_json(cm, "cm.json");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_NEAR(edge_length_mm(r->pieces[0].edges[0]), 100, 1e-9);
  EXPECT_NEAR(r->pieces[0].notches[0].position_mm, 50, 1e-9);
  ASSERT_TRUE(r->pieces[0].placement.has_value());
  EXPECT_NEAR(r->pieces[0].placement->translation_mm.z, 30, 1e-9);
  // 90 degrees about y takes piece x to body -z.
  EXPECT_NEAR(r->pieces[0].placement->rotation[6], -1, 1e-12);
}

TEST(PatternJson, ClockwiseOutlineIsReversedWithAWarning) {
  const std::string cw = R"({"pieces": [{"name": "sq", "edges": [
      {"name": "a", "from": [0, 0]}, {"name": "b", "from": [0, 10]}, {"name": "c", "from": [10, 10]},
      {"name": "d", "from": [10, 0]}], "notches": [{"edge": "a", "at": 2}]}]})";
  auto r = read_pattern_json(cw, "cw.json");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_GT(signed_area(outline(r->pieces[0])), 0);
  ASSERT_EQ(r->warnings.size(), 1u);
  EXPECT_NE(r->warnings[0].find("'sq'"), std::string::npos);
  // The notch 2 mm from the start of "a" stays at the same place on the reversed edge.
  const Notch& n = r->pieces[0].notches[0];
  EXPECT_EQ(r->pieces[0].edges[n.edge].name, "a");
  EXPECT_NEAR(point_along_edge(r->pieces[0].edges[n.edge], n.position_mm).y, 2, 1e-9);
}

TEST(PatternJson, SyntaxErrorNamesLineAndColumn) {
  std::string m = error_of("{\n  \"pieces\": [\n    {\"name\": \"a\",,}\n  ]\n}");
  EXPECT_NE(m.find("bad.json:3:"), std::string::npos) << m;
}

TEST(PatternJson, WrongTypesAndMissingFieldsNameTheJsonPointer) {
  std::string m = error_of(R"({"pieces": [{"name": "a", "edges": [{"name": "x", "from": "here"}, {"from": [1, 0]}]}]})");
  EXPECT_NE(m.find("bad.json: /pieces/0/edges/0/from"), std::string::npos) << m;
  m = error_of(R"({"pieces": [{"edges": []}]})");
  EXPECT_NE(m.find("/pieces/0"), std::string::npos) << m;
  EXPECT_NE(m.find("name"), std::string::npos) << m;
  m = error_of(R"({"units": "furlong", "pieces": []})");
  EXPECT_NE(m.find("/units"), std::string::npos) << m;
  m = error_of(R"({"pieces": [{"name": "a", "edges": [{"from": [0, 0], "curve": "cubic", "controls": [[1, 1]]}, {"from": [1, 0]}]}]})");
  EXPECT_NE(m.find("/pieces/0/edges/0/controls"), std::string::npos) << m;
  m = error_of(R"({"pieces": [{"name": "a", "edges": [{"from": [0, 0], "curve": "spline"}, {"from": [1, 0]}]}]})");
  EXPECT_NE(m.find("/pieces/0/edges/0/curve"), std::string::npos) << m;
  m = error_of(R"({"pieces": {"name": "a"}})");
  EXPECT_NE(m.find("/pieces: expected an array"), std::string::npos) << m;
  m = error_of("[1, 2]");
  EXPECT_NE(m.find("bad.json: /: expected an object"), std::string::npos) << m;
}

TEST(PatternJson, UnknownReferencesAreNamed) {
  const std::string base = R"({"pieces": [{"name": "sq", "edges": [
      {"name": "a", "from": [0, 0]}, {"name": "b", "from": [10, 0]}, {"name": "c", "from": [10, 10]},
      {"name": "d", "from": [0, 10]}]}], "stitches": [STITCH]})";
  auto with = [&](const std::string& s) {
    std::string t = base;
    t.replace(t.find("STITCH"), 6, s);
    return t;
  };
  auto r = read_pattern_json(with(R"({"a": {"piece": "sq", "edge": "a"}, "b": {"piece": "circle", "edge": "x"}})"), "s.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kUnknownReference);
  EXPECT_NE(r.error().message.find("/stitches/0/b/piece: no piece named 'circle'"), std::string::npos) << r.error().message;
  r = read_pattern_json(with(R"({"a": {"piece": "sq", "edge": "zz"}, "b": {"piece": "sq", "edge": "c"}})"), "s.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("piece 'sq' has no edge 'zz'"), std::string::npos) << r.error().message;
  r = read_pattern_json(with(R"({"a": {"piece": "sq", "edge": "a", "to": "nn"}, "b": {"piece": "sq", "edge": "c"}})"), "s.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("no notch 'nn'"), std::string::npos) << r.error().message;
  // A valid self-stitch of two opposite sides passes the reader; spans by number resolve.
  r = read_pattern_json(with(R"({"a": {"piece": "sq", "edge": "a", "from": 2, "to": 8}, "b": {"piece": "sq", "edge": "c", "from": "start", "to": 6}})"), "s.json");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_NEAR(span_length_mm(*r, r->stitches[0].a), 6, 1e-9);
}

TEST(PatternJson, BadFoldAndQuantityAreRejected) {
  std::string m = error_of(R"({"pieces": [{"name": "a", "fold": "curvy", "edges": [
      {"name": "curvy", "from": [0, 0], "curve": "quadratic", "controls": [[5, 5]]}, {"name": "b", "from": [10, 0]},
      {"name": "c", "from": [10, 10]}]}]})");
  EXPECT_NE(m.find("not straight"), std::string::npos) << m;
  EXPECT_NE(m.find("/pieces/0/fold"), std::string::npos) << m;
  m = error_of(R"({"pieces": [{"name": "a", "quantity": 3, "mirror_pairs": true, "edges": [
      {"from": [0, 0]}, {"from": [10, 0]}, {"from": [10, 10]}]}]})");
  EXPECT_NE(m.find("/pieces/0/quantity"), std::string::npos) << m;
  m = error_of(R"({"pieces": [{"name": "a", "quantity": 0, "edges": [{"from": [0, 0]}, {"from": [10, 0]}]}]})");
  EXPECT_NE(m.find("/pieces/0/quantity"), std::string::npos) << m;
}

TEST(PatternJson, MissingFileIsAnIoError) {
  auto r = load_pattern_json("/nonexistent/pattern.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kIo);
  EXPECT_NE(r.error().message.find("/nonexistent/pattern.json"), std::string::npos);
}

TEST(PatternJson, DeepNestingIsRefused) {
  std::string deep(10000, '[');
  std::string m = error_of(deep);
  EXPECT_NE(m.find("nested deeper"), std::string::npos) << m;
}

}  // namespace
}  // namespace tp::geometry
