// tests/geometry/nesting/strip_nester_test.cpp: the strip engine: every layout checked exactly
// (no overlap, inside the strip, gaps and hazards honoured), budgets, determinism and errors.
#include "geometry/nesting/strip_nester.h"

#include <gtest/gtest.h>

#include <map>

#include "geometry/nesting/esicup.h"
#include "tests/geometry/nesting/layout_checker.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

StripProblem instance(const std::string& name) {
  auto p = load_esicup(test::shared_data_dir() / "esicup" / (name + ".json"));
  EXPECT_TRUE(p.has_value()) << (p ? "" : p.error().what());
  return p ? *p : StripProblem{};
}

test::Pts pts(const Polygon& p) {
  test::Pts out;
  for (Vec2 v : p) out.push_back({v.x, v.y});
  return out;
}

std::vector<test::Pts> placed_pieces(const StripProblem& p, const StripSolution& s) {
  std::vector<test::Pts> out;
  for (const StripPlacement& pl : s.placements)
    out.push_back(test::transform_piece(pts(p.items[pl.item].shape), pl.rotation_deg, pl.mirror, pl.translation.x,
                                        pl.translation.y));
  return out;
}

// Every copy placed once, each with an allowed pose, and the layout exactly legal.
void expect_valid(const StripProblem& p, const StripSolution& s, double gap = 0, double edge = 0, double start = 0) {
  std::map<int, int> count;
  for (const StripPlacement& pl : s.placements) {
    ++count[pl.item];
    ASSERT_GE(pl.item, 0);
    ASSERT_LT(pl.item, static_cast<int>(p.items.size()));
    EXPECT_EQ(pl.item_id, p.items[pl.item].id);
    const StripItem& it = p.items[pl.item];
    bool allowed = false;
    for (const StripPose& q : it.poses)
      allowed |= q.mirror == pl.mirror && (it.free_rotation || q.rotation_deg == pl.rotation_deg);
    EXPECT_TRUE(allowed) << "item " << pl.item << " placed at " << pl.rotation_deg << " deg, mirror " << pl.mirror;
  }
  for (int k : s.unplaced) ++count[k];
  for (size_t i = 0; i < p.items.size(); ++i) EXPECT_EQ(count[static_cast<int>(i)], p.items[i].demand) << "item " << i;
  std::vector<test::Pts> hazards;
  for (const Polygon& h : p.hazards) hazards.push_back(pts(h));
  const auto r = test::check_layout(placed_pieces(p, s), start, edge, s.length, p.width - edge, gap, hazards);
  EXPECT_TRUE(r.ok()) << r.first << " (" << r.overlaps << " overlaps, " << r.outside << " outside, " << r.too_close
                      << " too close)";
  // The reported length is the used length: some piece reaches it.
  double max_x = 0;
  for (const test::Pts& q : placed_pieces(p, s))
    for (auto [x, y] : q) max_x = std::max(max_x, x);
  EXPECT_NEAR(max_x, s.length, 1e-9 * std::max(1.0, s.length));
}

StripOptions quick(std::uint64_t work, std::uint64_t seed = 1) {
  StripOptions o;
  o.time_limit_s = 60;  // the work budget ends these runs, so they are reproducible
  o.work_limit = work;
  o.seed = seed;
  return o;
}

TEST(StripNester, ConstructivePlacementOfShirtsIsLegal) {
  const StripProblem p = instance("shirts");
  StripOptions o;
  o.improve = false;
  auto s = nest_strip(p, o);
  ASSERT_TRUE(s) << s.error().what();
  EXPECT_EQ(s->placements.size(), 99u);
  EXPECT_TRUE(s->unplaced.empty());
  expect_valid(p, *s);
  EXPECT_GT(s->density, 0.70);
  EXPECT_EQ(s->length, s->constructive_length);
}

TEST(StripNester, SearchShortensTheStripAndStaysLegal) {
  for (const char* name : {"albano", "dagli", "trousers"}) {
    SCOPED_TRACE(name);
    const StripProblem p = instance(name);
    auto s = nest_strip(p, quick(300));
    ASSERT_TRUE(s) << s.error().what();
    expect_valid(p, *s);
    EXPECT_LT(s->length, s->constructive_length * 0.97) << "the search should gain at least 3 % of length";
    EXPECT_EQ(s->iterations, 300u);
  }
}

TEST(StripNester, SameSeedSameLayoutWhateverTheThreadCount) {
  const StripProblem p = instance("dagli");
  StripOptions a = quick(150, 7), b = quick(150, 7), c = quick(150, 8);
  a.threads = 1;
  b.threads = 2;
  auto sa = nest_strip(p, a), sb = nest_strip(p, b), sc = nest_strip(p, c);
  ASSERT_TRUE(sa && sb && sc);
  ASSERT_EQ(sa->placements.size(), sb->placements.size());
  for (size_t i = 0; i < sa->placements.size(); ++i) {
    EXPECT_EQ(sa->placements[i].translation, sb->placements[i].translation) << i;
    EXPECT_EQ(sa->placements[i].rotation_deg, sb->placements[i].rotation_deg) << i;
  }
  EXPECT_EQ(sa->length, sb->length);
  bool differs = false;
  for (size_t i = 0; i < sa->placements.size(); ++i) differs |= !(sa->placements[i].translation == sc->placements[i].translation);
  EXPECT_TRUE(differs) << "another seed should give another layout";
}

TEST(StripNester, GapsAndMarginsAreKept) {
  const StripProblem p = instance("albano");
  StripOptions o = quick(120);
  o.gap = 40;
  o.edge_margin = 100;
  o.start_margin = 250;
  auto s = nest_strip(p, o);
  ASSERT_TRUE(s) << s.error().what();
  expect_valid(p, *s, 40, 100, 250);
}

TEST(StripNester, HazardsAreAvoided) {
  StripProblem p = instance("dagli");
  // A defect across the middle of the strip, and a triangle at the bottom edge.
  p.hazards.push_back({{10, 20}, {14, 20}, {14, 45}, {10, 45}});
  p.hazards.push_back({{25, 0}, {35, 0}, {30, 12}});
  auto s = nest_strip(p, quick(150));
  ASSERT_TRUE(s) << s.error().what();
  expect_valid(p, *s);
}

TEST(StripNester, FreeRotationAndMirrorsAreUsedOnlyWhenAllowed) {
  StripProblem p;
  p.name = "l-shapes";
  p.width = 30;
  StripItem l;
  l.shape = {{0, 0}, {20, 0}, {20, 5}, {5, 5}, {5, 12}, {0, 12}};
  l.demand = 6;
  l.free_rotation = true;
  l.poses = {{0, false}, {0, true}};
  p.items.push_back(l);
  StripItem fixed = l;
  fixed.id = 1;
  fixed.free_rotation = false;
  fixed.poses = {{90, false}};
  fixed.demand = 3;
  p.items.push_back(fixed);
  auto s = nest_strip(p, quick(100));
  ASSERT_TRUE(s) << s.error().what();
  expect_valid(p, *s);
  for (const StripPlacement& pl : s->placements) {
    if (pl.item != 1) continue;
    EXPECT_EQ(pl.rotation_deg, 90.0);
  }
}

TEST(StripNester, LengthLimitLeavesWhatDoesNotFit) {
  const StripProblem p = instance("shirts");
  StripOptions o = quick(50);
  o.length_limit = 30;
  auto s = nest_strip(p, o);
  ASSERT_TRUE(s) << s.error().what();
  EXPECT_FALSE(s->unplaced.empty());
  EXPECT_FALSE(s->placements.empty());
  EXPECT_LE(s->length, 30.0);
  expect_valid(p, *s);
}

TEST(StripNester, CancelledBeforeStartFails) {
  const StripProblem p = instance("dagli");
  CancelToken cancel;
  cancel.cancel();
  auto s = nest_strip(p, quick(10), cancel);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kCancelled);
}

TEST(StripNester, RejectsBrokenItemsNamingThem) {
  StripProblem p;
  p.name = "broken";
  p.width = 10;
  StripItem bowtie;
  bowtie.id = 42;
  bowtie.shape = {{0, 0}, {4, 4}, {4, 0}, {0, 4}};
  p.items.push_back(bowtie);
  auto s = nest_strip(p, quick(10));
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidPattern);
  EXPECT_NE(s.error().message.find("id 42"), std::string::npos) << s.error().message;
  EXPECT_NE(s.error().message.find("crosses itself"), std::string::npos) << s.error().message;

  p.items[0].shape = {{0, 0}, {30, 0}, {30, 12}, {0, 12}};  // 12 high: wider than the strip
  p.items[0].poses = {{0, false}, {180, false}};
  s = nest_strip(p, quick(10));
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kNesting);
  EXPECT_NE(s.error().message.find("does not fit the strip width"), std::string::npos) << s.error().message;

  p.width = -1;
  s = nest_strip(p, quick(10));
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
}

TEST(StripNester, PlacePolygonAppliesMirrorThenRotationThenTranslation) {
  StripPlacement pl;
  pl.rotation_deg = 90;
  pl.mirror = true;
  pl.translation = {10, 0};
  const Polygon out = place_polygon({{1, 0}, {0, 2}}, pl);
  // (1,0) -> mirror (-1,0) -> rotate 90 (0,-1) -> (10,-1); (0,2) -> (0,2) -> (-2,0) -> (8,0).
  EXPECT_NEAR(out[0].x, 10, 1e-12);
  EXPECT_NEAR(out[0].y, -1, 1e-12);
  EXPECT_NEAR(out[1].x, 8, 1e-12);
  EXPECT_NEAR(out[1].y, 0, 1e-12);
}

}  // namespace
}  // namespace tp::geometry
