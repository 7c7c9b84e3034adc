// tests/geometry/nesting/nest_budget_test.cpp: a work-only budget (no time limit) reads no
// clock: the markers repeat exactly, whatever else runs, and the budget is the work done.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "geometry/nesting/nest_pieces.h"

namespace tp::geometry {
namespace {

std::vector<NestItem> pieces() {
  std::vector<NestItem> items;
  const Polygon shapes[] = {{{0, 0}, {260, 0}, {270, 420}, {200, 520}, {150, 480}, {110, 480}, {60, 520}, {-10, 420}},
                            {{0, 0}, {300, 0}, {280, 180}, {150, 240}, {20, 180}},
                            {{0, 0}, {200, 0}, {200, 60}, {0, 60}}};
  for (int i = 0; i < 3; ++i) {
    NestItem it;
    it.piece = i;
    it.name = "piece " + std::to_string(i);
    it.outline_mm = shapes[i];
    it.quantity = i == 2 ? 4 : 2;
    items.push_back(it);
  }
  return items;
}

NestOptions work_only(std::uint64_t iterations) {
  NestOptions o;
  o.fabric_width_mm = 700;
  o.gap_mm = 4;
  o.end_margin_mm = 15;
  o.time_limit_s = 0;
  o.work_limit = iterations;
  o.seed = 5;
  return o;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(NestBudget, AWorkOnlyBudgetRepeatsBitForBitAndSpendsExactlyItsIterations) {
  NestStats sa, sb;
  auto a = nest_pieces(pieces(), work_only(80), {}, &sa);
  ASSERT_TRUE(a) << a.error().message;
  // The second run competes with busy threads of this process for the cores.
  std::atomic<bool> stop{false};
  std::vector<std::thread> busy;
  for (unsigned i = 0; i < 2 * std::max(1u, std::thread::hardware_concurrency()); ++i)
    busy.emplace_back([&] {
      volatile double x = 1;
      while (!stop.load()) x = x * 1.0000001 + 1e-9;
    });
  auto b = nest_pieces(pieces(), work_only(80), {}, &sb);
  stop = true;
  for (auto& t : busy) t.join();
  ASSERT_TRUE(b) << b.error().message;
  ASSERT_EQ(a->size(), b->size());
  for (size_t k = 0; k < a->size(); ++k) {
    EXPECT_TRUE(same_bits((*a)[k].length_mm, (*b)[k].length_mm)) << (*a)[k].length_mm << " " << (*b)[k].length_mm;
    ASSERT_EQ((*a)[k].placements.size(), (*b)[k].placements.size());
    for (size_t i = 0; i < (*a)[k].placements.size(); ++i) {
      const auto &p = (*a)[k].placements[i], &q = (*b)[k].placements[i];
      EXPECT_EQ(p.piece, q.piece);
      EXPECT_TRUE(same_bits(p.rotation_deg, q.rotation_deg));
      EXPECT_TRUE(same_bits(p.offset_mm.x, q.offset_mm.x) && same_bits(p.offset_mm.y, q.offset_mm.y)) << i;
    }
  }
  EXPECT_EQ(sa.iterations, sb.iterations);
  ASSERT_EQ(sa.iterations.size(), 1u);
  EXPECT_EQ(sa.iterations[0], 80u);
}

TEST(NestBudget, TheWorkHookReportsBoundedRisingProgressAndLeavesTheMarkersAlone) {
  auto plain = nest_pieces(pieces(), work_only(200));
  NestOptions o = work_only(200);
  std::vector<std::uint64_t> done;
  o.on_work = [&](std::uint64_t d, std::uint64_t total) {
    EXPECT_EQ(total, 200u);
    done.push_back(d);
  };
  auto hooked = nest_pieces(pieces(), o);
  ASSERT_TRUE(plain && hooked);
  // Whole percents of the budget: more than a few calls, never more than 100, rising to the end.
  EXPECT_GE(done.size(), 10u);
  EXPECT_LE(done.size(), 100u);
  for (size_t i = 1; i < done.size(); ++i) EXPECT_GT(done[i], done[i - 1]);
  ASSERT_FALSE(done.empty());
  EXPECT_LE(done.back(), 200u);
  EXPECT_GE(done.back(), 198u);
  ASSERT_EQ(plain->size(), hooked->size());
  for (size_t k = 0; k < plain->size(); ++k) {
    EXPECT_TRUE(same_bits((*plain)[k].length_mm, (*hooked)[k].length_mm));
    ASSERT_EQ((*plain)[k].placements.size(), (*hooked)[k].placements.size());
    for (size_t i = 0; i < (*plain)[k].placements.size(); ++i) {
      const auto &p = (*plain)[k].placements[i], &q = (*hooked)[k].placements[i];
      EXPECT_TRUE(same_bits(p.rotation_deg, q.rotation_deg));
      EXPECT_TRUE(same_bits(p.offset_mm.x, q.offset_mm.x) && same_bits(p.offset_mm.y, q.offset_mm.y)) << i;
    }
  }
}

TEST(NestBudget, MoreIterationsNeverLengthenTheMarker) {
  auto few = nest_pieces(pieces(), work_only(5));
  auto many = nest_pieces(pieces(), work_only(120));
  ASSERT_TRUE(few && many);
  EXPECT_LE(many->front().length_mm, few->front().length_mm);
}

}  // namespace
}  // namespace tp::geometry
