// tests/rip/swath/pass_plan_test.cpp: the weave covers every fabric row and column exactly once, for
// 1..8 passes, nozzle pitches 1..3 and rolls shorter and longer than the head.
#include "rip/swath/pass_plan.h"

#include <map>
#include <vector>

#include <gtest/gtest.h>

namespace tp::rip {
namespace {

device::PrinterModel head(int nozzles, int pitch) {
  device::PrinterModel p;
  p.nozzles_per_ink = nozzles;
  p.nozzle_pitch_rows = pitch;
  return p;
}

/// Prints every pass onto a counter grid and returns the counts.
std::vector<int> coverage(const PassPlan& plan, std::int64_t height, int width) {
  std::vector<int> hits(static_cast<size_t>(height) * width, 0);
  for (std::int64_t k = first_pass(plan); k <= last_pass(plan, height); ++k) {
    const PassRows pr = rows_of_pass(plan, k, height);
    for (int r = 0; r < pr.rows; ++r) {
      const std::int64_t y = pr.first_row + static_cast<std::int64_t>(r) * plan.nozzle_pitch_rows;
      EXPECT_GE(y, 0);
      EXPECT_LT(y, height);
      const int n = pr.first_nozzle + r;
      EXPECT_EQ(y, pass_origin_row(plan, k) + static_cast<std::int64_t>(n) * plan.nozzle_pitch_rows);
      const int phase = column_phase(plan, y, visit_of_nozzle(plan, n));
      for (int x = phase; x < width; x += plan.passes) ++hits[static_cast<size_t>(y) * width + x];
    }
  }
  return hits;
}

TEST(PassPlan, EveryPixelIsPrintedExactlyOnce) {
  for (int pitch : {1, 2, 3}) {
    for (int passes : {1, 2, 4, 8}) {
      auto plan = make_pass_plan(head(64, pitch), passes);
      ASSERT_TRUE(plan) << plan.error().what();
      for (std::int64_t height : {1, 7, 63, 64, 65, 200, 517}) {
        const auto hits = coverage(*plan, height, 19);
        for (size_t i = 0; i < hits.size(); ++i)
          ASSERT_EQ(hits[i], 1) << "pitch " << pitch << " passes " << passes << " height " << height << " row "
                                << i / 19 << " col " << i % 19;
      }
    }
  }
}

TEST(PassPlan, EachRowIsVisitedOncePerPassInTimeOrder) {
  auto plan = make_pass_plan(head(64, 3), 4);
  ASSERT_TRUE(plan);
  // visits[y] collects (pass, visit); visits must be 0,1,2,3 in pass order.
  std::map<std::int64_t, std::vector<std::pair<std::int64_t, int>>> visits;
  const std::int64_t height = 400;
  for (std::int64_t k = first_pass(*plan); k <= last_pass(*plan, height); ++k) {
    const PassRows pr = rows_of_pass(*plan, k, height);
    for (int r = 0; r < pr.rows; ++r)
      visits[pr.first_row + r * plan->nozzle_pitch_rows].push_back({k, visit_of_nozzle(*plan, pr.first_nozzle + r)});
  }
  ASSERT_EQ(visits.size(), 400u);
  for (const auto& [y, v] : visits) {
    ASSERT_EQ(v.size(), 4u) << y;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(v[static_cast<size_t>(i)].second, i) << "row " << y;
  }
}

TEST(PassPlan, FeedAndNozzlesFollowTheHead) {
  auto single = make_pass_plan(device::PrinterModel{}, 1);
  ASSERT_TRUE(single);
  EXPECT_EQ(single->feed_rows, 1280);
  EXPECT_EQ(first_pass(*single), 0);
  EXPECT_EQ(last_pass(*single, 1280), 0);
  EXPECT_EQ(last_pass(*single, 1281), 1);
  auto four = make_pass_plan(device::PrinterModel{}, 4);
  ASSERT_TRUE(four);
  EXPECT_EQ(four->feed_rows, 320);
  EXPECT_EQ(first_pass(*four), -3);
  // Pitch 2 with 64 nozzles and 2 passes: feed 32 shares a factor with 2, so 62 nozzles (feed 31).
  auto woven = make_pass_plan(head(64, 2), 2);
  ASSERT_TRUE(woven);
  EXPECT_EQ(woven->nozzles_used, 62);
  EXPECT_EQ(woven->feed_rows, 31);
}

TEST(PassPlan, RejectsImpossiblePlans) {
  auto zero = make_pass_plan(device::PrinterModel{}, 0);
  ASSERT_FALSE(zero);
  EXPECT_NE(zero.error().message.find("passes 0"), std::string::npos);
  EXPECT_FALSE(make_pass_plan(head(4, 1), 8));
  EXPECT_FALSE(make_pass_plan(head(0, 1), 1));
}

}  // namespace
}  // namespace tp::rip
