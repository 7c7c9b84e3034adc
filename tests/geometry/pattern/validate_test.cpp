// tests/geometry/pattern/validate_test.cpp: each validation problem is found and named.
#include "geometry/pattern/validate.h"

#include <gtest/gtest.h>

#include "geometry/pattern/curve.h"

namespace tp::geometry {
namespace {

Piece polygon_piece(const std::string& name, const std::vector<Vec2>& corners) {
  Piece p;
  p.name = name;
  for (size_t i = 0; i < corners.size(); ++i)
    p.edges.push_back(make_line_edge("e" + std::to_string(i), corners[i], corners[(i + 1) % corners.size()]));
  return p;
}

Pattern two_squares() {
  Pattern pat;
  pat.pieces.push_back(polygon_piece("front", {{0, 0}, {100, 0}, {100, 200}, {0, 200}}));
  pat.pieces.push_back(polygon_piece("back", {{0, 0}, {100, 0}, {100, 200}, {0, 200}}));
  // front's right side to back's left side: lengths 200 and 200.
  pat.stitches.push_back(Stitch{EdgeSpan{0, 1}, EdgeSpan{1, 3}});
  return pat;
}

std::string only_problem(const Pattern& pat, const ValidationOptions& o = {}) {
  auto problems = find_pattern_problems(pat, o);
  EXPECT_EQ(problems.size(), 1u);
  std::string all;
  for (const Error& e : problems) all += e.message + "\n";
  return all;
}

TEST(Validate, SoundPatternPasses) {
  Status s = validate_pattern(two_squares());
  EXPECT_TRUE(s.has_value()) << s.error().what();
}

TEST(Validate, OpenOutlineNamesBothEdgesAndTheGap) {
  Pattern pat = two_squares();
  pat.pieces[0].edges[2].points_mm.front() = {100, 205};
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("piece 'front': outline is open: edge 'e1' ends at (100.00, 200.00) but edge 'e2' starts"), std::string::npos) << m;
  EXPECT_NE(m.find("gap 5.00 mm"), std::string::npos) << m;
}

TEST(Validate, SelfIntersectionIsFound) {
  Pattern pat;
  // A bow tie: the edges e1 and e3 cross at (50, 50).
  pat.pieces.push_back(polygon_piece("bow", {{0, 0}, {100, 100}, {100, 0}, {0, 100}}));
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("piece 'bow': outline intersects itself: edge 'e0' meets edge 'e2' near (50.00, 50.00)"), std::string::npos) << m;
}

TEST(Validate, ZeroLengthEdgeIsNamed) {
  Pattern pat;
  pat.pieces.push_back(polygon_piece("p", {{0, 0}, {100, 0}, {100, 0}, {0, 100}}));
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("piece 'p': edge 'e1' has zero length"), std::string::npos) << m;
}

TEST(Validate, ClockwiseOutlineIsReportedUnlessAllowed) {
  Pattern pat;
  pat.pieces.push_back(polygon_piece("cw", {{0, 0}, {0, 100}, {100, 100}, {100, 0}}));
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("piece 'cw': outline is clockwise"), std::string::npos) << m;
  ValidationOptions o;
  o.require_counter_clockwise = false;
  EXPECT_TRUE(find_pattern_problems(pat, o).empty());
}

TEST(Validate, DuplicateNamesAreReported) {
  Pattern pat = two_squares();
  pat.pieces[1].name = "front";
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("duplicate piece name 'front'"), std::string::npos) << m;
  pat = two_squares();
  pat.pieces[0].edges[2].name = "e1";
  m = only_problem(pat);
  EXPECT_NE(m.find("piece 'front': duplicate edge name 'e1'"), std::string::npos) << m;
}

TEST(Validate, StitchLengthMismatchReportsBothLengths) {
  Pattern pat = two_squares();
  pat.stitches[0].b = EdgeSpan{1, 0};  // 200 mm against 100 mm
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("stitch #0: piece 'front' edge 'e1' (1) is 200.00 mm but piece 'back' edge 'e0' (0) is 100.00 mm"),
            std::string::npos) << m;
  // Within the tolerance: 200 against 199.5 passes (allowed max(1 mm, 0.5 % of 200) = 1 mm).
  pat = two_squares();
  pat.pieces[1].edges[3].points_mm.back().y = 0.5;
  pat.pieces[1].edges[0].points_mm.front().y = 0.5;
  EXPECT_TRUE(find_pattern_problems(pat).empty());
}

TEST(Validate, UnknownPieceEdgeAndSpanOutOfRange) {
  Pattern pat = two_squares();
  pat.stitches[0].b.piece = 7;
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("stitch #0: piece #7 does not exist"), std::string::npos) << m;
  pat = two_squares();
  pat.stitches[0].b.edge = 9;
  m = only_problem(pat);
  EXPECT_NE(m.find("stitch #0: piece 'back' has no edge #9"), std::string::npos) << m;
  pat = two_squares();
  pat.stitches[0].a = EdgeSpan{0, 1, 50, 250};
  pat.stitches[0].b = EdgeSpan{1, 3, 0, 200};
  m = only_problem(pat);
  EXPECT_NE(m.find("span [50.00, 250.00] mm of piece 'front' edge 'e1' (1) is out of range (edge length 200.00 mm)"),
            std::string::npos) << m;
}

TEST(Validate, NotchOffItsEdgeAndBadDartAreReported) {
  Pattern pat = two_squares();
  pat.pieces[0].notches.push_back(Notch{"n", 0, 150});
  std::string m = only_problem(pat);
  EXPECT_NE(m.find("piece 'front': notch 'n' at 150.00 mm lies off edge 'e0' (length 100.00 mm)"), std::string::npos) << m;
  pat = two_squares();
  pat.pieces[0].darts.push_back(Dart{"d", 1, 1});
  m = only_problem(pat);
  EXPECT_NE(m.find("dart 'd' has the same edge as both legs"), std::string::npos) << m;
}

TEST(Validate, NonFiniteCoordinatesAreCaught) {
  Pattern pat = two_squares();
  pat.pieces[0].edges[1].points_mm.push_back({std::nan(""), 0});
  auto problems = find_pattern_problems(pat);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems[0].message.find("non-finite"), std::string::npos);
}

TEST(Validate, ValidatePatternSummarisesTheRest) {
  Pattern pat = two_squares();
  pat.pieces[1].name = "front";
  pat.stitches[0].b.piece = 9;
  Status s = validate_pattern(pat);
  ASSERT_FALSE(s.has_value());
  EXPECT_NE(s.error().message.find("and 1 more problems"), std::string::npos) << s.error().message;
}

}  // namespace
}  // namespace tp::geometry
