// tests/geometry/pattern/garmentcode_test.cpp: GarmentCode specifications from the shared data, and broken ones.
#include "geometry/pattern/import/garmentcode.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/pattern/placement.h"
#include "geometry/pattern/validate.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

std::filesystem::path spec(const std::string& name) {
  return tp::test::shared_data_dir() / "garmentcode/patterns" / (name + "_specification.json");
}

struct Expect {
  const char* name;
  size_t panels;
  size_t stitches;
  size_t length_mismatches;  ///< stitches whose sides differ in the source itself (gathers, eased seams)
};

class GarmentCodeFiles : public ::testing::TestWithParam<Expect> {};

TEST_P(GarmentCodeFiles, LoadRightSideUpAndValidate) {
  const Expect& x = GetParam();
  auto r = load_garmentcode(spec(x.name));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_EQ(r->pieces.size(), x.panels);
  EXPECT_EQ(r->stitches.size(), x.stitches);
  EXPECT_TRUE(r->warnings.empty()) << r->warnings.front();
  for (const Piece& p : r->pieces) {
    ASSERT_TRUE(p.placement.has_value()) << p.name;
    EXPECT_GT(signed_area(outline(p)), 0) << p.name;
    // Right side up: the piece frame's normal (x cross y mapped to 3D) points away from the body
    // axis, i.e. the outside of the fabric faces outwards.
    const auto& m = p.placement->rotation;
    Vec3 normal = cross(Vec3{m[0], m[3], m[6]}, Vec3{m[1], m[4], m[7]});
    Vec2 c = bounds(outline(p)).min * 0.5 + bounds(outline(p)).max * 0.5;
    Vec3 centre = place_point(*p.placement, c);
    Vec3 outward{centre.x, 0, centre.z};
    EXPECT_GT(dot(normal, outward), 0) << p.name;
  }
  // Stitches whose sides differ in length in the source (GarmentCode gathers or eases them) are
  // marked gathered with their ratio, and then the pattern validates.
  size_t gathered = 0;
  for (const Stitch& st : r->stitches) {
    if (st.ease_ratio == 0) continue;
    ++gathered;
    const double la = span_length_mm(*r, st.a), lb = span_length_mm(*r, st.b);
    EXPECT_NEAR(st.ease_ratio, std::max(la, lb) / std::min(la, lb), 1e-9);
  }
  EXPECT_EQ(gathered, x.length_mismatches);
  auto problems = find_pattern_problems(*r);
  EXPECT_TRUE(problems.empty()) << problems.front().message;
  // Unmarked, the same mismatches are refused with both lengths.
  Pattern unmarked = *r;
  for (Stitch& st : unmarked.stitches) st.ease_ratio = 0;
  problems = find_pattern_problems(unmarked);
  EXPECT_EQ(problems.size(), x.length_mismatches);
  for (const Error& e : problems) EXPECT_NE(e.message.find(" mm but "), std::string::npos) << e.message;
}

INSTANTIATE_TEST_SUITE_P(SharedData, GarmentCodeFiles,
                         ::testing::Values(Expect{"dress_pencil", 6, 23, 11}, Expect{"hoody_mean", 6, 12, 0},
                                           Expect{"js_mean_all", 12, 57, 6}, Expect{"shirt_mean", 8, 18, 0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GarmentCode, FlattenedLengthsMatchAnIndependentComputation) {
  auto r = load_garmentcode(spec("dress_pencil"));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  // skirt_front e7 and skirt_back e2 measured by numeric integration of the Beziers: 235.68 and
  // 247.80 mm; the flattened polylines agree within 0.05 mm.
  const Piece& f = r->pieces[find_piece(*r, "skirt_front")];
  const Piece& b = r->pieces[find_piece(*r, "skirt_back")];
  EXPECT_NEAR(edge_length_mm(f.edges[7]), 235.68, 0.05);
  EXPECT_NEAR(edge_length_mm(b.edges[2]), 247.80, 0.05);
}

TEST(GarmentCode, UnitsPlacementAndSidesAreInTheBodyFrame) {
  auto r = load_garmentcode(spec("shirt_mean"));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Pattern& p = *r;
  // Panel order follows the file's panel_order.
  EXPECT_EQ(p.pieces[0].name, "right_sleeve_b");
  int front = find_piece(p, "left_ftorso"), back = find_piece(p, "left_btorso");
  int lsleeve = find_piece(p, "left_sleeve_f"), rsleeve = find_piece(p, "right_sleeve_f");
  ASSERT_GE(front, 0);
  ASSERT_GE(back, 0);
  EXPECT_EQ(p.pieces[front].role, "front");
  EXPECT_EQ(p.pieces[back].role, "back");
  EXPECT_EQ(p.pieces[lsleeve].role, "sleeve");
  // cm to mm: the front torso sits 25 cm in front of the body axis, 94.57 cm up.
  EXPECT_NEAR(p.pieces[front].placement->translation_mm.z, 250, 1e-6);
  EXPECT_NEAR(p.pieces[front].placement->translation_mm.y, 945.7103829637592, 1e-6);
  EXPECT_LT(p.pieces[back].placement->translation_mm.z, 0);
  // The wearer's left sleeve is on +x.
  Vec2 c = bounds(outline(p.pieces[lsleeve])).min;
  EXPECT_GT(place_point(*p.pieces[lsleeve].placement, c).x, 0);
  EXPECT_LT(place_point(*p.pieces[rsleeve].placement, bounds(outline(p.pieces[rsleeve])).min).x, 0);
}

TEST(GarmentCode, MirroredBackPanelsKeepTheir3dPositions) {
  auto r = load_garmentcode(spec("shirt_mean"));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  // left_btorso is stored clockwise (seen from inside); its vertex 2 is at (x, y) = file vertex,
  // placed at translation (0, 94.66, -20) cm without rotation.
  const Piece& b = r->pieces[find_piece(*r, "left_btorso")];
  Vec3 p = place_point(*b.placement, b.edges[2].points_mm.front());
  EXPECT_NEAR(p.x, 12.8474 * 10, 1e-6);
  EXPECT_NEAR(p.y, 45.89674322821761 * 10 + 946.6024668570651, 1e-6);
  EXPECT_NEAR(p.z, -200, 1e-6);
}

TEST(GarmentCode, CircleArcsHaveTheirRadius) {
  auto r = load_garmentcode(spec("hoody_mean"));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  // left_ftorso edge 4 is a circle of radius 11.564 cm, bulging left (right = 0).
  int f = find_piece(*r, "left_ftorso");
  ASSERT_GE(f, 0);
  const Edge& e = r->pieces[f].edges[4];
  ASSERT_EQ(e.curve, EdgeCurve::kArc);
  for (Vec2 q : e.points_mm) EXPECT_NEAR(norm(q - e.control_mm[0]), 115.64126734773824, 1e-6);
  Vec2 a = e.points_mm.front(), b = e.points_mm.back(), m = e.control_mm[1];
  EXPECT_GT(cross(b - a, m - a), 0) << "a left-bulging arc lies to the left of its chord";
}

TEST(GarmentCode, DartStitchesPairMouthWithMouth) {
  auto r = load_garmentcode(spec("dress_pencil"));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Stitch& s = r->stitches[0];  // skirt_back e4 <-> e5: the legs of a dart
  const Piece& p = r->pieces[s.a.piece];
  EXPECT_FALSE(s.same_direction);
  Vec2 a_start = p.edges[s.a.edge].points_mm.front(), b_end = p.edges[s.b.edge].points_mm.back();
  EXPECT_NEAR(a_start.y, b_end.y, 1e-9);  // both mouth ends on the waist line
}

std::string error_of(const std::string& text) {
  auto r = read_garmentcode(text, "gc.json");
  EXPECT_FALSE(r.has_value());
  return r ? std::string() : r.error().message;
}

const char* kSquare = R"({"pattern": {"panels": {"p": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
  "vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
  "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}},
  "stitches": [[{"panel": "p", "edge": 1}, {"panel": "p", "edge": 3}, "right_wrong"]]},
  "properties": {"units_in_meter": 100, "curvature_coords": "relative"}})";

TEST(GarmentCode, MinimalPanelAndRightWrongStitch) {
  auto r = read_garmentcode(kSquare, "gc.json");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_NEAR(edge_length_mm(r->pieces[0].edges[0]), 100, 1e-9);
  ASSERT_EQ(r->stitches.size(), 1u);
  EXPECT_TRUE(r->stitches[0].same_direction);
}

TEST(GarmentCode, BrokenSpecificationsNameTheField) {
  auto broken = [](const std::string& from, const std::string& to) {
    std::string t = kSquare;
    auto pos = t.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    return t.replace(pos, from.size(), to);
  };
  std::string m = error_of(broken(R"("edge": 3})", R"("edge": 4})"));
  EXPECT_NE(m.find("/pattern/stitches/0/1/edge: panel 'p' has edges 0..3, not 4"), std::string::npos) << m;
  m = error_of(broken(R"({"panel": "p", "edge": 1})", R"({"panel": "q", "edge": 1})"));
  EXPECT_NE(m.find("/pattern/stitches/0/0/panel: no panel 'q'"), std::string::npos) << m;
  m = error_of(broken(R"({"endpoints": [1, 2]})", R"({"endpoints": [2, 3]})"));
  EXPECT_NE(m.find("/pattern/panels/p/edges/1/endpoints: edge starts at vertex 2 but the previous edge ends at vertex 1"),
            std::string::npos) << m;
  m = error_of(broken(R"({"endpoints": [3, 0]})", R"({"endpoints": [3, 1]})"));
  EXPECT_NE(m.find("edge loop does not close"), std::string::npos) << m;
  m = error_of(broken(R"({"endpoints": [0, 1]})", R"({"endpoints": [0, 1], "curvature": {"type": "circle", "params": [0.2, 0, 1]}})"));
  EXPECT_NE(m.find("/pattern/panels/p/edges/0/curvature/params: circle radius 2.00 mm is shorter than half its chord (50.00 mm)"),
            std::string::npos) << m;
  m = error_of(broken(R"({"endpoints": [0, 1]})", R"({"endpoints": [0, 1], "curvature": {"type": "bspline", "params": []}})"));
  EXPECT_NE(m.find("/pattern/panels/p/edges/0/curvature/type: unknown curvature 'bspline'"), std::string::npos) << m;
  m = error_of(broken("[10, 0]", "[10, \"x\"]"));
  EXPECT_NE(m.find("/pattern/panels/p/vertices/1/1: expected a number"), std::string::npos) << m;
  m = error_of(broken(R"("units_in_meter": 100)", R"("units_in_meter": -1)"));
  EXPECT_NE(m.find("/properties/units_in_meter"), std::string::npos) << m;
  m = error_of(R"({"panels": {}})");
  EXPECT_NE(m.find("no \"pattern\""), std::string::npos) << m;
}

}  // namespace
}  // namespace tp::geometry
