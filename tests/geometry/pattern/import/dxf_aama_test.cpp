// tests/geometry/pattern/dxf_aama_test.cpp: DXF-AAMA pieces: the example file, generated variants, broken files.
#include "geometry/pattern/import/dxf_aama.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "geometry/pattern/validate.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

/// Writes DXF group pairs, enough for the tests' blocks.
class Dxf {
 public:
  Dxf& g(int code, const std::string& v) {
    s_ << code << "\n" << v << "\n";
    return *this;
  }
  Dxf& g(int code, double v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return g(code, o.str());
  }
  Dxf& header_units(int insunits) { return g(0, "SECTION").g(2, "HEADER").g(9, "$INSUNITS").g(70, std::to_string(insunits)).g(0, "ENDSEC"); }
  Dxf& begin_blocks() { return g(0, "SECTION").g(2, "BLOCKS"); }
  Dxf& block(const std::string& name) { return g(0, "BLOCK").g(8, "1").g(2, name).g(70, "0").g(10, 0.0).g(20, 0.0); }
  Dxf& end_block() { return g(0, "ENDBLK"); }
  Dxf& end_section() { return g(0, "ENDSEC"); }
  Dxf& line(const std::string& layer, Vec2 a, Vec2 b) {
    return g(0, "LINE").g(8, layer).g(10, a.x).g(20, a.y).g(11, b.x).g(21, b.y);
  }
  Dxf& point(const std::string& layer, Vec2 p) { return g(0, "POINT").g(8, layer).g(10, p.x).g(20, p.y); }
  Dxf& text(const std::string& layer, const std::string& t) { return g(0, "TEXT").g(8, layer).g(10, 0.0).g(20, 0.0).g(1, t); }
  Dxf& lwpolyline(const std::string& layer, const std::vector<Vec2>& pts, const std::vector<double>& bulges = {}) {
    g(0, "LWPOLYLINE").g(8, layer).g(90, std::to_string(pts.size())).g(70, "1");
    for (size_t i = 0; i < pts.size(); ++i) {
      g(10, pts[i].x).g(20, pts[i].y);
      if (i < bulges.size() && bulges[i] != 0) g(42, bulges[i]);
    }
    return *this;
  }
  Dxf& arc(const std::string& layer, Vec2 c, double r, double a0, double a1) {
    return g(0, "ARC").g(8, layer).g(10, c.x).g(20, c.y).g(40, r).g(50, a0).g(51, a1);
  }
  Dxf& circle(const std::string& layer, Vec2 c, double r) { return g(0, "CIRCLE").g(8, layer).g(10, c.x).g(20, c.y).g(40, r); }
  std::string str() const { return s_.str() + "0\nEOF\n"; }

 private:
  std::ostringstream s_;
};

TEST(DxfAama, ExampleSkirtWithCutAndSewLines) {
  auto r = load_dxf_aama(tp::test::source_dir() / "examples/patterns/skirt_aama.dxf");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_EQ(r->size, "38");
  EXPECT_TRUE(r->warnings.empty()) << r->warnings.front();
  ASSERT_EQ(r->pieces.size(), 3u);
  // FRONT: the sew line (not the 10-30 mm larger cut line) is the outline, unfolded at the mirror line.
  const Piece& front = r->pieces[0];
  EXPECT_EQ(front.name, "FRONT");
  EXPECT_EQ(front.role, "front");
  EXPECT_EQ(front.material, "SHELL");
  Box2 box = bounds(outline(front));
  EXPECT_NEAR(box.min.x, -250, 1e-9);
  EXPECT_NEAR(box.max.x, 250, 1e-9);
  EXPECT_NEAR(box.min.y, 0, 1e-9);
  ASSERT_TRUE(front.fold_line_mm.has_value());
  // The hip notch drawn square to the cut line at y = 300 meets the sew line at x = 250 - 10 * 300 / 450.
  ASSERT_EQ(front.notches.size(), 2u);
  Vec2 n = point_along_edge(front.edges[front.notches[0].edge], front.notches[0].position_mm);
  EXPECT_NEAR(n.x, 250 - 10.0 * 300 / 450, 0.01);
  EXPECT_NEAR(n.y, 300, 0.01);
  EXPECT_TRUE(front.grain.has_value());
  // BACK: quantity 2 with "Mirror: Y", split at its turn points, with its waist dart and drill hole.
  EXPECT_EQ(r->pieces[1].name, "BACK_l");
  EXPECT_EQ(r->pieces[2].name, "BACK_r");
  EXPECT_TRUE(r->pieces[2].mirrored);
  const Piece& back = r->pieces[1];
  EXPECT_EQ(back.edges.size(), 8u);
  ASSERT_EQ(back.darts.size(), 1u);
  EXPECT_NEAR(back.edges[back.darts[0].leg_a].points_mm.back().y, 480, 1e-9);
  ASSERT_EQ(back.drill_holes.size(), 1u);
  EXPECT_EQ(back.drill_holes[0].diameter_mm, 3);
  Status s = validate_pattern(*r);
  EXPECT_TRUE(s.has_value()) << s.error().what();
}

TEST(DxfAama, InchesLineChainsArcsAndCircles) {
  // A 4 x 3 inch panel drawn as separate LINEs and an ARC (a half circle of radius 1.5 on the
  // right side), one line reversed, with a drill CIRCLE of radius 0.125.
  Dxf d;
  d.header_units(1).begin_blocks().block("PANEL");
  d.line("1", {0, 0}, {4, 0}).line("1", {4, 3}, {0, 3}).line("1", {0, 3}, {0, 0});
  d.arc("1", {4, 1.5}, 1.5, -90, 90);
  d.circle("13", {2, 1.5}, 0.125);
  d.text("1", "Piece Name: Panel\\PQuantity: 3");
  d.end_block().end_section();
  auto r = read_dxf_aama(d.str(), "inch.dxf");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pieces.size(), 3u);
  EXPECT_EQ(r->pieces[0].name, "Panel_1");
  const Piece& p = r->pieces[0];
  Box2 box = bounds(outline(p));
  EXPECT_NEAR(box.width(), 5.5 * 25.4, 0.06);  // the arc's extreme may fall between flattened points
  EXPECT_NEAR(box.height(), 3 * 25.4, 1e-6);
  EXPECT_NEAR(signed_area(outline(p)), (12 + 3.14159265358979 * 1.5 * 1.5 / 2) * 25.4 * 25.4, 20);
  ASSERT_EQ(p.drill_holes.size(), 1u);
  EXPECT_NEAR(p.drill_holes[0].diameter_mm, 6.35, 1e-9);
  // The arc continues the top and bottom lines smoothly, so only the left side's ends are corners.
  ASSERT_EQ(p.edges.size(), 2u);
  EXPECT_EQ(p.edges[0].curve, EdgeCurve::kPolyline);
}

TEST(DxfAama, BulgedPolylineIsAnArc) {
  Dxf d;
  d.begin_blocks().block("D");
  // A half disc: straight diameter from (100, 0) to (-100, 0)... drawn as a bulge of 1 from
  // (-100, 0) to (100, 0) (counter-clockwise, below the chord), then straight back.
  d.lwpolyline("1", {{-100, 0}, {100, 0}}, {1, 0});
  d.end_block().end_section();
  auto r = read_dxf_aama(d.str(), "disc.dxf");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  Box2 box = bounds(outline(r->pieces[0]));
  EXPECT_NEAR(box.min.y, -100, 0.05);
  EXPECT_NEAR(box.max.y, 0, 1e-9);
}

TEST(DxfAama, BrokenFilesNameFileAndLine) {
  auto r = read_dxf_aama("0\nSECTION\n2\nBLOCKS\nabc\nBLOCK\n", "bad.dxf");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("bad.dxf:5: group code 'abc' is not an integer"), std::string::npos) << r.error().message;
  r = read_dxf_aama("0\nSECTION\n2", "short.dxf");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("short.dxf:3: group code 2 has no value"), std::string::npos) << r.error().message;
  Dxf open;
  open.begin_blocks().block("OPEN").line("1", {0, 0}, {10, 0}).line("1", {10, 0}, {10, 10}).end_block().end_section();
  r = read_dxf_aama(open.str(), "open.dxf");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("block 'OPEN': the boundary (layer 1) does not close"), std::string::npos) << r.error().message;
  Dxf empty;
  empty.begin_blocks().block("*Model_Space").end_block().end_section();
  r = read_dxf_aama(empty.str(), "empty.dxf");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("empty.dxf: no piece"), std::string::npos) << r.error().message;
}

TEST(DxfAama, OddAnnotationsAreWarnedNotFatal) {
  Dxf d;
  d.begin_blocks().block("A").lwpolyline("1", {{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  d.text("15", "Quantity: lots").point("4", {50, 50});
  d.end_block().block("A").lwpolyline("1", {{0, 0}, {20, 0}, {20, 20}}).end_block().end_section();
  auto r = read_dxf_aama(d.str(), "odd.dxf");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pieces.size(), 2u);
  EXPECT_EQ(r->pieces[1].name, "A_2");
  ASSERT_EQ(r->warnings.size(), 3u);
  EXPECT_NE(r->warnings[0].find("notch at"), std::string::npos) << r->warnings[0];
  EXPECT_NE(r->warnings[1].find("quantity 'lots'"), std::string::npos) << r->warnings[1];
  EXPECT_NE(r->warnings[2].find("renamed 'A_2'"), std::string::npos) << r->warnings[2];
}

}  // namespace
}  // namespace tp::geometry
