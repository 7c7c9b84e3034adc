// tests/geometry/pattern/freesewing_svg_test.cpp: FreeSewing SVGs from the shared data, and broken or odd ones.
#include "geometry/pattern/import/freesewing_svg.h"

#include <gtest/gtest.h>

#include "geometry/pattern/validate.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

std::filesystem::path fs_file(const std::string& design, int size) {
  return tp::test::shared_data_dir() / "freesewing" / (design + "-cisFemaleAdult" + std::to_string(size) + ".svg");
}

const Piece& piece(const Pattern& p, const std::string& name) {
  int i = find_piece(p, name);
  EXPECT_GE(i, 0) << name;
  return p.pieces[std::max(i, 0)];
}

struct Design {
  const char* name;
  std::vector<std::string> pieces;
};

class FreeSewingFiles : public ::testing::TestWithParam<std::tuple<Design, int>> {};

TEST_P(FreeSewingFiles, LoadAsSoundWholePieces) {
  const auto& [design, size] = GetParam();
  auto r = load_freesewing_svg(fs_file(design.name, size));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_EQ(r->name, design.name);
  EXPECT_EQ(r->size, "cisFemaleAdult" + std::to_string(size));
  std::vector<std::string> names;
  for (const Piece& p : r->pieces) names.push_back(p.name);
  EXPECT_EQ(names, design.pieces);
  EXPECT_TRUE(r->warnings.empty()) << r->warnings.front();
  Status s = validate_pattern(*r);
  EXPECT_TRUE(s.has_value()) << s.error().what();
  for (const Piece& p : r->pieces) {
    EXPECT_TRUE(p.grain.has_value()) << p.name;
    EXPECT_EQ(p.material, "fabric") << p.name;
    EXPECT_FALSE(p.fold_edge.has_value()) << p.name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, FreeSewingFiles,
    ::testing::Combine(::testing::Values(Design{"teagan", {"front", "back", "sleeve_l", "sleeve_r"}},
                                         Design{"penelope", {"back_l", "back_r", "front", "waistband"}},
                                         Design{"bella", {"back_l", "back_r", "frontSideDart", "sleeve_l", "sleeve_r"}}),
                       ::testing::Values(28, 34, 42)),
    [](const auto& info) { return std::string(std::get<0>(info.param).name) + std::to_string(std::get<1>(info.param)); });

TEST(FreeSewing, TeaganFrontIsUnfoldedSymmetricAndUpright) {
  auto r = load_freesewing_svg(fs_file("teagan", 34));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Piece& front = piece(*r, "front");
  Box2 box = bounds(outline(front));
  // The half is 265.5 mm wide from the fold; whole, it spans -265.5..265.5.
  EXPECT_NEAR(box.min.x, -265.5, 1e-9);
  EXPECT_NEAR(box.max.x, 265.5, 1e-9);
  // y up: the hem (y = 598 on the sheet) is the bottom, the shoulder (y = 9.47) near the top.
  EXPECT_NEAR(box.min.y, -598, 1e-9);
  EXPECT_NEAR(box.max.y, -9.47, 1e-9);
  ASSERT_TRUE(front.fold_line_mm.has_value());
  EXPECT_NEAR((*front.fold_line_mm)[0].x, 0, 1e-9);
  // The armhole notch (198.07, 146.47) is on an edge, and mirrored on the other side.
  ASSERT_EQ(front.notches.size(), 2u);
  Vec2 n0 = point_along_edge(front.edges[front.notches[0].edge], front.notches[0].position_mm);
  Vec2 n1 = point_along_edge(front.edges[front.notches[1].edge], front.notches[1].position_mm);
  EXPECT_NEAR(n0.x, 198.07, 0.05);
  EXPECT_NEAR(n0.y, -146.47, 0.05);
  EXPECT_NEAR(n1.x, -198.07, 0.05);
  // The back notch is a double notch: two slits 6 mm apart, on each side.
  EXPECT_EQ(piece(*r, "back").notches.size(), 4u);
  // The sleeve cap is one smooth edge holding the front notch and the double back notch.
  const Piece& sleeve = piece(*r, "sleeve_l");
  ASSERT_EQ(sleeve.notches.size(), 3u);
  EXPECT_EQ(sleeve.notches[0].edge, sleeve.notches[1].edge);
  EXPECT_EQ(sleeve.notches[1].edge, sleeve.notches[2].edge);
}

TEST(FreeSewing, PenelopeBackPairDartsAndFoldedWaistband) {
  auto r = load_freesewing_svg(fs_file("penelope", 34));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Piece& bl = piece(*r, "back_l");
  const Piece& br = piece(*r, "back_r");
  EXPECT_FALSE(bl.mirrored);
  EXPECT_TRUE(br.mirrored);
  EXPECT_NEAR(signed_area(outline(bl)), signed_area(outline(br)), 1e-6);
  // Two waist darts per back; their legs are equal and meet at the tip.
  ASSERT_EQ(bl.darts.size(), 2u);
  for (const Dart& d : bl.darts) {
    EXPECT_NEAR(edge_length_mm(bl.edges[d.leg_a]), edge_length_mm(bl.edges[d.leg_b]), 0.5);
    EXPECT_EQ(bl.edges[d.leg_a].points_mm.back(), bl.edges[d.leg_b].points_mm.front());
  }
  EXPECT_EQ(piece(*r, "front").darts.size(), 4u);
  // The hem fold line (a fabric path that is not closed) is kept as an internal line.
  EXPECT_EQ(bl.internal_lines.size(), 1u);
  // The waistband is folded along its short top edge: unfolded it is the whole waist, 2 x 378.79.
  const Piece& wb = piece(*r, "waistband");
  Box2 box = bounds(outline(wb));
  EXPECT_NEAR(box.height(), 2 * 378.79, 1e-6);
  EXPECT_NEAR(box.width(), 60, 1e-6);
  EXPECT_EQ(wb.role, "waistband");
}

TEST(FreeSewing, BellaDartsAndInteriorMarks) {
  auto r = load_freesewing_svg(fs_file("bella", 34));
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Piece& f = piece(*r, "frontSideDart");
  EXPECT_EQ(f.role, "front");
  // The waist dart and the side dart, each on both halves.
  EXPECT_EQ(f.darts.size(), 4u);
  // The notch 12.5 mm above the waist dart's tip marks the bust point: a drill mark, mirrored.
  bool mark = false;
  for (const DrillHole& h : f.drill_holes) mark = mark || (std::abs(h.position_mm.x - 88) < 1e-6 && std::abs(h.position_mm.y + 275) < 1e-6);
  EXPECT_TRUE(mark);
  EXPECT_EQ(f.drill_holes.size(), 3u);
  for (const DrillHole& h : f.drill_holes) EXPECT_EQ(h.diameter_mm, 0);
}

TEST(FreeSewing, KeepsHalvesWhenAsked) {
  PatternImportOptions o;
  o.unfold_cut_on_fold = false;
  o.expand_quantity = false;
  auto r = load_freesewing_svg(fs_file("teagan", 34), o);
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pieces.size(), 3u);
  const Piece& front = piece(*r, "front");
  ASSERT_TRUE(front.fold_edge.has_value());
  const Edge& fe = front.edges[*front.fold_edge];
  EXPECT_NEAR(fe.points_mm.front().x, 0, 1e-9);
  EXPECT_NEAR(fe.points_mm.back().x, 0, 1e-9);
}

std::string svg_with(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\"><g id=\"fs-container\"><g id=\"fs-stack-x.panel\">"
         "<g id=\"fs-stack-x.panel-part-x.panel\" transform=\"translate(0, 0)\">" +
         body + "</g></g></g></svg>";
}

TEST(FreeSewing, OddButWellFormedMarkupIsRead) {
  // What SVG producers emit that a naive reader trips on: a comment, a CDATA section, escaped
  // '<', an entity XML does not define (kept as written), a <text> split into <tspan>s, a
  // transform on the seam path, and xlink:href on the notch.
  std::string body =
      "<!-- seam --><path class='fabric' id=\"fs-1\" transform=\"translate(10,0)\" d=\"M0,0 L100,0 L100,50 L0,50 z\" />"
      "<text><tspan>plugin-annotations:cut,2,plugin-annotations:from,</tspan><tspan>plugin-annotations:lining, a &lt; "
      "b "
      "&nbsp;</tspan><![CDATA[ <raw> ]]></text>"
      "<use x=\"60\" y=\"0\" xlink:href=\"#notch\"></use><text>closed</text>";
  auto r = read_freesewing_svg(svg_with(body), "odd.svg");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pieces.size(), 2u);
  EXPECT_EQ(r->pieces[0].name, "panel_1");
  EXPECT_EQ(r->pieces[0].material, "lining");  // the annotation says what to cut it from
  Box2 box = bounds(outline(r->pieces[0]));
  EXPECT_NEAR(box.min.x, 10, 1e-9);
  EXPECT_NEAR(box.min.y, -50, 1e-9);
  ASSERT_EQ(r->pieces[0].notches.size(), 1u);
}

TEST(FreeSewing, MarkupThatIsNotXmlNamesFileLineAndByte) {
  // Unquoted attribute values, a stray '<' in text and an unclosed element are not XML: the
  // importer says where instead of guessing what was meant.
  for (const std::string& body :
       {std::string("\n\n<path class=fabric d=\"M0,0 L1,0 L0,1 z\" />"), std::string("\n\n<text>a < b</text>"),
        std::string("\n<path class=\"fabric\" d=\"M0,0 L1,0 L0,1 z\" />\n<text>unclosed")}) {
    auto r = read_freesewing_svg(svg_with(body), "odd.svg");
    ASSERT_FALSE(r.has_value()) << body;
    EXPECT_EQ(r.error().code, ErrorCode::kParse);
    EXPECT_NE(r.error().message.find("odd.svg:3: not well-formed XML: "), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(" (byte "), std::string::npos) << r.error().message;
  }
}

TEST(FreeSewing, BadPathDataNamesFileLineAndPath) {
  auto r = read_freesewing_svg(svg_with("\n\n<path class=\"fabric\" id=\"fs-9\" d=\"M 0,0 L 10,0 Q 5\" />"), "bad.svg");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_NE(r.error().message.find("bad.svg:3: part 'panel': path 'fs-9': path data:"), std::string::npos) << r.error().message;
}

TEST(FreeSewing, NoPartsOrNoSeamLineIsAnError) {
  auto r = read_freesewing_svg("<svg><path class=\"fabric\" d=\"M0,0 L1,0 L0,1 z\"/></svg>", "plain.svg");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("plain.svg: no FreeSewing part groups"), std::string::npos);
  r = read_freesewing_svg(svg_with("<path class=\"fabric sa\" d=\"M0,0 L1,0 L0,1 z\"/>"), "sa.svg");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("no part has a closed seam line"), std::string::npos) << r.error().message;
}

TEST(FreeSewing, MissingFileIsAnIoError) {
  auto r = load_freesewing_svg("/nonexistent.svg");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kIo);
}

}  // namespace
}  // namespace tp::geometry
