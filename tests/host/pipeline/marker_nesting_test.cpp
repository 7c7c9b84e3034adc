// tests/host/pipeline/marker_nesting_test.cpp: a job's marker fields become the nester's roll and
// budget as the marker stage (and the RIP benchmark through it) uses them.
#include "host/pipeline/marker_nesting.h"

#include <gtest/gtest.h>

namespace tp::host {
namespace {

TEST(MarkerNestOptions, AnIterationBudgetReadsNoClock) {
  MarkerSpec m;
  m.fabric_width_mm = 1200;
  m.gap_mm = 5;
  m.edge_margin_mm = 8;
  m.time_limit_s = 7;
  m.iterations = 20000;
  m.seed = 3;
  const geometry::NestOptions o = marker_nest_options(m);
  EXPECT_EQ(o.fabric_width_mm, 1200);
  EXPECT_EQ(o.gap_mm, 5);
  EXPECT_EQ(o.selvedge_margin_mm, 8);
  EXPECT_EQ(o.end_margin_mm, 5);
  EXPECT_EQ(o.time_limit_s, 0);
  EXPECT_EQ(o.work_limit, 20000u);
  EXPECT_EQ(o.seed, 3u);
  EXPECT_EQ(o.max_length_mm, 0);
  EXPECT_FALSE(o.on_work);
}

TEST(MarkerNestOptions, ATimeBudgetAndDefectsAndALongestMarker) {
  MarkerSpec m;
  m.time_limit_s = 4;
  m.iterations = 0;
  m.max_length_mm = 2500;
  m.defects.push_back({});
  m.defects.back().x_mm = 100;
  m.defects.back().y_mm = 200;
  m.defects.back().width_mm = 30;
  m.defects.back().length_mm = 40;
  const geometry::NestOptions o = marker_nest_options(m);
  EXPECT_EQ(o.time_limit_s, 4);
  EXPECT_EQ(o.work_limit, 0u);
  EXPECT_EQ(o.max_length_mm, 2500);
  ASSERT_EQ(o.defects_mm.size(), 1u);
  const geometry::Polygon expected{{100, 200}, {130, 200}, {130, 240}, {100, 240}};
  ASSERT_EQ(o.defects_mm[0].size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(o.defects_mm[0][i].x, expected[i].x) << i;
    EXPECT_EQ(o.defects_mm[0][i].y, expected[i].y) << i;
  }
}

}  // namespace
}  // namespace tp::host
