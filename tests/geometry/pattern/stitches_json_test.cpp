// tests/geometry/pattern/stitches_json_test.cpp: suggested stitches written as a stitches file and read back.
#include <gtest/gtest.h>

#include "geometry/pattern/stitches_json.h"

namespace tp::geometry {
namespace {

Piece rectangle(const std::string& name, double w, double h) {
  Piece p;
  p.name = name;
  p.edges = {Edge{"hem", EdgeCurve::kLine, {}, {{0, 0}, {w, 0}}}, Edge{"right", EdgeCurve::kLine, {}, {{w, 0}, {w, h}}},
             Edge{"top", EdgeCurve::kLine, {}, {{w, h}, {0, h}}}, Edge{"left", EdgeCurve::kLine, {}, {{0, h}, {0, 0}}}};
  return p;
}

Pattern two_panels() {
  Pattern p;
  p.name = "panels";
  p.pieces = {rectangle("front", 300, 400), rectangle("back", 300, 400)};
  return p;
}

TEST(StitchesJson, RoundTripKeepsSidesSpansDirectionAndEase) {
  Pattern p = two_panels();
  std::vector<StitchSuggestion> s{
      {{Stitch{EdgeSpan{0, 1, 0, -1}, EdgeSpan{1, 3, 0, -1}, false}}, 0.91, "lengths 400/400 mm"},
      {{Stitch{EdgeSpan{1, 1, 50, 350}, EdgeSpan{0, 3, 0, 300}, true, 1.25}}, 0.75, "split; eased"}};
  const std::string text = write_stitches_json(p, s);
  EXPECT_NE(text.find("\"tp-stitches\""), std::string::npos);
  EXPECT_NE(text.find("\"score\": 0.91"), std::string::npos);
  EXPECT_NE(text.find("lengths 400/400 mm"), std::string::npos);
  auto back = read_stitches_json(text, "panels.stitches.json", p);
  ASSERT_TRUE(back) << back.error().what();
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[0].a.piece, 0);
  EXPECT_EQ((*back)[0].a.edge, 1);
  EXPECT_EQ((*back)[0].b.piece, 1);
  EXPECT_EQ((*back)[0].b.edge, 3);
  EXPECT_FALSE((*back)[0].same_direction);
  EXPECT_EQ((*back)[0].ease_ratio, 0);
  EXPECT_DOUBLE_EQ((*back)[1].a.from_mm, 50);
  EXPECT_DOUBLE_EQ((*back)[1].a.to_mm, 350);
  EXPECT_DOUBLE_EQ((*back)[1].b.to_mm, 300);
  EXPECT_TRUE((*back)[1].same_direction);
  EXPECT_DOUBLE_EQ((*back)[1].ease_ratio, 1.25);
  // The pattern passed in is not changed.
  EXPECT_TRUE(p.stitches.empty());
}

TEST(StitchesJson, BadReferencesAndFormatsNameFileAndPointer) {
  Pattern p = two_panels();
  auto r = read_stitches_json(R"({"stitches": [{"a": {"piece": "front", "edge": "right"},
                                                 "b": {"piece": "sleve", "edge": "left"}}]})",
                              "s.json", p);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kUnknownReference);
  EXPECT_NE(r.error().message.find("s.json: /stitches/0/b/piece: no piece named 'sleve'"), std::string::npos)
      << r.error().message;
  auto f = read_stitches_json(R"({"format": "tp-pattern", "stitches": []})", "s.json", p);
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("/format"), std::string::npos);
  auto none = read_stitches_json(R"({"units": "mm"})", "s.json", p);
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("needs \"stitches\""), std::string::npos);
  auto syntax = read_stitches_json("{", "s.json", p);
  ASSERT_FALSE(syntax);
  EXPECT_EQ(syntax.error().code, ErrorCode::kParse);
}

}  // namespace
}  // namespace tp::geometry
