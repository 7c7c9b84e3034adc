// tests/rip/colour/tone_curve_test.cpp: linearisation curves: parsing, errors that name the field,
// monotone evaluation through the points.
#include "rip/colour/tone_curve.h"

#include <gtest/gtest.h>

namespace tp::rip {
namespace {

TEST(ToneCurve, ParsesPercentPairsAndPassesThroughThem) {
  auto c = parse_tone_curve("0:0, 25:19.5; 50:42\n75:70 100:100", "ink 'cyan' linearisation");
  ASSERT_TRUE(c) << c.error().what();
  ASSERT_EQ(c->points.size(), 5u);
  EXPECT_DOUBLE_EQ(evaluate(*c, 0.25), 0.195);
  EXPECT_DOUBLE_EQ(evaluate(*c, 0.5), 0.42);
  EXPECT_DOUBLE_EQ(evaluate(*c, 1.0), 1.0);
  // Monotone everywhere, and between its neighbours.
  double prev = -1;
  for (int i = 0; i <= 1000; ++i) {
    const double y = evaluate(*c, i / 1000.0);
    EXPECT_GE(y, prev);
    prev = y;
  }
  const double mid = evaluate(*c, 0.375);
  EXPECT_GT(mid, 0.195);
  EXPECT_LT(mid, 0.42);
}

TEST(ToneCurve, FlatStretchesStayFlat) {
  ToneCurve c{{{0, 0}, {0.3, 0.5}, {0.6, 0.5}, {1, 1}}};
  ASSERT_TRUE(validate_tone_curve(c, "test"));
  for (double x = 0.3; x <= 0.6; x += 0.01) EXPECT_NEAR(evaluate(c, x), 0.5, 1e-12) << x;
}

TEST(ToneCurve, ErrorsNameTheCurveAndThePair) {
  struct Case {
    const char* text;
    const char* expect;
  } cases[] = {
      {"0:0 50 100:100", "pair 2"},           {"0:0 50:x 100:100", "output 'x'"},
      {"0:0 60:50 40:60 100:100", "does not increase"}, {"0:0 50:60 70:40 100:100", "decreases"},
      {"0:0 50:120 100:100", "outside 0..100"}, {"10:0 100:100", "from 0 to 100"},
      {"0:0", "at least 2"},                  {"", "at least 2"},
  };
  for (const auto& k : cases) {
    auto r = parse_tone_curve(k.text, "ink 'black' linearisation");
    ASSERT_FALSE(r) << k.text;
    EXPECT_EQ(r.error().code, ErrorCode::kColour);
    EXPECT_NE(r.error().message.find("ink 'black' linearisation"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(k.expect), std::string::npos) << k.text << " -> " << r.error().message;
  }
}

}  // namespace
}  // namespace tp::rip
