// tests/geometry/pattern/suggest_stitches_test.cpp: stitch suggestions on FreeSewing and DXF patterns without stitches.
#include "geometry/pattern/suggest_stitches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/pattern/import/dxf_aama.h"
#include "geometry/pattern/import/freesewing_svg.h"
#include "geometry/pattern/validate.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

std::string side(const Pattern& p, const EdgeSpan& s) {
  return p.pieces[s.piece].name + "." + p.pieces[s.piece].edges[s.edge].name;
}

/// "a <-> b" for every suggested stitch (spans not shown), for set comparison.
std::set<std::string> seams(const Pattern& p, const std::vector<StitchSuggestion>& sug) {
  std::set<std::string> out;
  for (const auto& s : sug)
    for (const Stitch& st : s.stitches) out.insert(side(p, st.a) + " <-> " + side(p, st.b));
  return out;
}

TEST(SuggestStitches, TeaganTshirtIsSewnTheWayItIsMeant) {
  auto r = load_freesewing_svg(tp::test::shared_data_dir() / "freesewing/teagan-cisFemaleAdult34.svg");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  auto sug = suggest_stitches(*r);
  // front/back: e1 side seam, e2 armhole, e3 shoulder, e4 neck (free), e0 hem (free); the
  // front's +x side is the wearer's left, the back's +x side the wearer's right, so sides cross.
  // The sleeve as drafted (front notch at +x) is a right sleeve: its cap takes the front's -x
  // armhole and the back's +x armhole.
  std::set<std::string> expected = {
      "sleeve_l.e1 <-> sleeve_l.e3",       "sleeve_r.e3 <-> sleeve_r.e1",
      "sleeve_l.e2 <-> front.e2_mirror",   "sleeve_l.e2 <-> back.e2",
      "sleeve_r.e2 <-> back.e2_mirror",    "sleeve_r.e2 <-> front.e2",
      "front.e1 <-> back.e1_mirror",       "front.e1_mirror <-> back.e1",
      "front.e3 <-> back.e3_mirror",       "front.e3_mirror <-> back.e3"};
  EXPECT_EQ(seams(*r, sug), expected);
  for (size_t i = 1; i < sug.size(); ++i) EXPECT_GE(sug[i - 1].score, sug[i].score);
  // Accepted, they validate (the cap's ease is within the default tolerance).
  Pattern sewn = *r;
  EXPECT_EQ(accept_suggestions(sewn, sug), 10);
  Status s = validate_pattern(sewn);
  EXPECT_TRUE(s.has_value()) << s.error().what();
  // The cap is split where the front armhole's share of its length ends.
  for (const auto& x : sug)
    if (x.stitches.size() == 2) {
      EXPECT_NEAR(x.stitches[0].a.to_mm, x.stitches[1].a.from_mm, 1e-9);
      EXPECT_NE(x.reason.find("notch groups 4 of 4"), std::string::npos) << x.reason;
    }
}

TEST(SuggestStitches, PenelopeSkirtDartsSidesAndCentreBack) {
  auto r = load_freesewing_svg(tp::test::shared_data_dir() / "freesewing/penelope-cisFemaleAdult34.svg");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  auto sug = suggest_stitches(*r);
  int darts = 0;
  for (const auto& s : sug) darts += s.reason.rfind("dart", 0) == 0;
  EXPECT_EQ(darts, 8);  // two per back, four on the front
  auto got = seams(*r, sug);
  // back_l as drafted (centre back at x = 0) is the wearer's right back.
  EXPECT_TRUE(got.count("back_r.e4 <-> front.e2")) << "left side seam";
  EXPECT_TRUE(got.count("back_l.e4 <-> front.e2_mirror")) << "right side seam";
  EXPECT_TRUE(got.count("back_l.e0 <-> back_r.e0")) << "centre back";
  // Waist segments between darts are level edges with nothing but their length in common: no
  // two of them are sewn to each other, only to the waistband.
  for (const std::string& s : got) {
    if (s.find("waistband") == std::string::npos) {
      EXPECT_EQ(s.find("front.e3"), std::string::npos) << s;
    }
  }
}

TEST(SuggestStitches, PenelopeWaistbandGoesRoundTheWholeWaistFromTheCentreBack) {
  auto r = load_freesewing_svg(tp::test::shared_data_dir() / "freesewing/penelope-cisFemaleAdult34.svg");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  auto sug = suggest_stitches(*r);
  const StitchSuggestion* band = nullptr;
  for (const auto& s : sug)
    if (s.reason.rfind("band", 0) == 0) band = &s;
  ASSERT_NE(band, nullptr) << "the waistband is not sewn";
  EXPECT_GE(band->score, SuggestOptions{}.min_score);
  // The waist between the darts: three segments per back half, five across the front.
  ASSERT_EQ(band->stitches.size(), 11u) << band->reason;
  std::set<std::string> waist;
  double at_mm = 0;
  for (const Stitch& st : band->stitches) {
    EXPECT_EQ(side(*r, st.a), "waistband.e0");
    EXPECT_NEAR(st.a.from_mm, at_mm, 1e-9) << "spans of the band follow each other";
    at_mm = st.a.to_mm;
    waist.insert(side(*r, st.b));
  }
  EXPECT_LT(band->stitches.back().a.to_mm, 0) << "the last span runs to the band's end";
  EXPECT_EQ(waist,
            (std::set<std::string>{"back_l.e5", "back_l.e8", "back_l.e11", "back_r.e5", "back_r.e8", "back_r.e11",
                                   "front.e3", "front.e6", "front.e9", "front.e6_mirror", "front.e3_mirror"}));
  // The band opens at the centre back (between the mirror copies), where the zip is.
  const std::string first = side(*r, band->stitches.front().b), last = side(*r, band->stitches.back().b);
  EXPECT_TRUE((first == "back_l.e11" && last == "back_r.e11") || (first == "back_r.e11" && last == "back_l.e11"))
      << first << " .. " << last;
  // The middle of the band is at the centre front.
  double front_from = 0, front_to = 0;
  for (const Stitch& st : band->stitches)
    if (side(*r, st.b) == "front.e9") front_from = st.a.from_mm, front_to = st.a.to_mm;
  EXPECT_NEAR((front_from + front_to) / 2, 757.58 / 2, 5);
}

TEST(SuggestStitches, DxfSkirtSideSeamsAcrossATurnPoint) {
  auto r = load_dxf_aama(tp::test::source_dir() / "examples/patterns/skirt_aama.dxf");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  auto sug = suggest_stitches(*r);
  ASSERT_FALSE(sug.empty());
  EXPECT_EQ(sug[0].score, 1.0);  // the back darts come first
  auto got = seams(*r, sug);
  // The front's smooth side seam meets the back's two edges either side of its hip turn point,
  // the hip notches in line.
  EXPECT_TRUE(got.count("FRONT.e1 <-> BACK_r.e1"));
  EXPECT_TRUE(got.count("FRONT.e1 <-> BACK_r.e2"));
  EXPECT_TRUE(got.count("FRONT.e1_mirror <-> BACK_l.e1"));
  EXPECT_TRUE(got.count("BACK_l.e7 <-> BACK_r.e7"));
  Pattern sewn = *r;
  accept_suggestions(sewn, sug);
  Status s = validate_pattern(sewn);
  EXPECT_TRUE(s.has_value()) << s.error().what();
}

TEST(SuggestStitches, BellasEasedBackShoulderIsMarkedEasedWithItsRatio) {
  // Bella's back shoulder (161.3 mm) is eased onto the front's (156.9 mm): beyond the default
  // tolerance (1 mm), so the suggestion marks it eased with the ratio and says so; the seams
  // whose sides agree stay plain, and the accepted pattern validates with the default tolerance.
  auto r = load_freesewing_svg(tp::test::shared_data_dir() / "freesewing/bella-cisFemaleAdult42.svg");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  auto sug = suggest_stitches(*r);
  int eased = 0, plain = 0;
  for (const auto& x : sug)
    for (const Stitch& st : x.stitches) {
      const double la = span_length_mm(*r, st.a), lb = span_length_mm(*r, st.b);
      const double ratio = std::max(la, lb) / std::min(la, lb);
      if (std::abs(la - lb) > std::max(1.0, 0.005 * std::max(la, lb))) {
        ++eased;
        EXPECT_NEAR(st.ease_ratio, ratio, 1e-12) << side(*r, st.a) << " <-> " << side(*r, st.b);
        EXPECT_NE(x.reason.find("eased"), std::string::npos) << x.reason;
      } else {
        ++plain;
        EXPECT_EQ(st.ease_ratio, 0) << side(*r, st.a) << " <-> " << side(*r, st.b);
      }
    }
  EXPECT_EQ(eased, 2);  // the two shoulders, about 1.028 : 1
  EXPECT_GT(plain, 10);
  Pattern sewn = *r;
  accept_suggestions(sewn, sug);
  Status s = validate_pattern(sewn);
  EXPECT_TRUE(s.has_value()) << s.error().what();
}

TEST(SuggestStitches, ExistingStitchesAndThresholdsAreRespected) {
  auto r = load_freesewing_svg(tp::test::shared_data_dir() / "freesewing/teagan-cisFemaleAdult34.svg");
  ASSERT_TRUE(r.has_value());
  Pattern p = *r;
  // Sew the sides by hand; the suggestions leave them alone.
  int front = find_piece(p, "front"), back = find_piece(p, "back");
  p.stitches.push_back(Stitch{EdgeSpan{front, find_edge(p.pieces[front], "e1"), 0, -1},
                              EdgeSpan{back, find_edge(p.pieces[back], "e1_mirror"), 0, -1}, false});
  auto sug = suggest_stitches(p);
  for (const std::string& s : seams(p, sug)) EXPECT_EQ(s.find("front.e1 "), std::string::npos) << s;
  SuggestOptions strict;
  strict.min_score = 0.99;
  for (const auto& x : suggest_stitches(p, strict)) ADD_FAILURE() << x.score << " " << x.reason;
  Pattern q = *r;
  EXPECT_EQ(accept_suggestions(q, suggest_stitches(*r), 0.89), 6);  // underarms (2) and caps (4) only
}

}  // namespace
}  // namespace tp::geometry
