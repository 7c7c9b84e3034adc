// geometry/nesting/internal/strip_search.cpp: exploration and compression phases around the
// separator, and the large-item swap that disrupts stuck layouts.
#include "geometry/nesting/internal/strip_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "geometry/nesting/internal/poles.h"

namespace tp::geometry::nesting {
namespace {

Vec2 box_centre(const Box2& b) { return (b.min + b.max) * 0.5; }

}  // namespace

void fit_strip(Layout& layout, QueryScratch& scratch) {
  layout.resize(layout.used_x_hi(), 1e300, scratch);
}

void disrupt(Layout& layout, double large_item_share, Rng& rng, QueryScratch& scratch) {
  const int n = layout.size();
  // The "large" copies: the biggest that together hold `large_item_share` of the hull area.
  std::vector<int> order;
  for (int k = 0; k < n; ++k)
    if (layout.item(k).present) order.push_back(k);
  if (order.size() < 2) return;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return layout.item(a).hull_area > layout.item(b).hull_area; });
  double total = 0;
  for (int k : order) total += layout.item(k).hull_area;
  double cum = 0, cutoff = 0;
  for (int k : order) {
    cum += layout.item(k).hull_area;
    cutoff = layout.item(k).hull_area;
    if (cum > large_item_share * total) break;
  }
  std::vector<int> large;
  for (int k : order)
    if (layout.item(k).hull_area >= cutoff) large.push_back(k);
  const int a = large[rng.below(large.size())];
  const Placed& pa = layout.item(a);
  // A partner of a visibly different size (swapping twins changes nothing), else anyone.
  std::vector<int> partners;
  for (int k : large) {
    const Placed& pk = layout.item(k);
    if (k != a && std::fabs(pk.hull_area - pa.hull_area) > 0.01 * pa.hull_area &&
        std::fabs(pk.diameter - pa.diameter) > 0.01 * pa.diameter)
      partners.push_back(k);
  }
  if (partners.empty())
    for (int k : order)
      if (k != a) partners.push_back(k);
  const int b = partners[rng.below(partners.size())];

  const Vec2 ca = box_centre(layout.item(a).box), cb = box_centre(layout.item(b).box);
  const Pose pose_a = layout.item(a).pose, pose_b = layout.item(b).pose;
  const Vec2 ta = layout.item(a).t, tb = layout.item(b).t;
  layout.place(a, pose_a, ta + (cb - ca), scratch, false);
  layout.place(b, pose_b, tb + (ca - cb), scratch, false);
  // Copies now under a swapped item move into the space it left.
  for (int moved : {a, b}) {
    const Vec2 back = moved == a ? ca - cb : cb - ca;
    const Polygon outline(layout.item(moved).pts.begin(), layout.item(moved).pts.end());
    for (int k = 0; k < n; ++k) {
      if (k == a || k == b) continue;
      const Placed& p = layout.item(k);
      if (!p.present || !point_in_polygon(outline, p.poles[0].c)) continue;
      layout.place(k, p.pose, p.t + back, scratch, false);
    }
  }
  layout.resize(layout.x_hi(), 1e300, scratch);
}

void explore(Layout& best, Separator& sep, const StripSearchConfig& config, Budget& budget, Rng& rng,
             const ImprovementHook& on_improvement, SearchStats& stats) {
  QueryScratch scratch;
  Layout cur = best;
  const double x_lo = best.ctx().x_lo;
  auto shrink_from = [&](const Layout& from) {
    cur = from;
    const double len = from.x_hi() - x_lo;
    cur.resize(x_lo + len * (1.0 - config.explore_shrink), x_lo + len / 2, scratch);
    sep.reseed(rng);
  };
  shrink_from(best);
  std::vector<std::pair<double, Layout>> pool;
  while (!budget.exhausted()) {
    if (sep.separate(cur, config.explore_separator, budget)) {
      ++stats.explore_feasible;
      fit_strip(cur, scratch);
      if (cur.x_hi() < best.x_hi()) {
        best = cur;
        if (on_improvement) on_improvement(best);
      }
      pool.clear();
      shrink_from(cur);
      continue;
    }
    if (budget.exhausted()) break;
    ++stats.explore_failed;
    // Stuck: remember this layout, restart from a good one of the pool, shaken.
    const double loss = cur.total_loss();
    auto at = std::upper_bound(pool.begin(), pool.end(), loss,
                               [](double l, const std::pair<double, Layout>& e) { return l < e.first; });
    pool.insert(at, {loss, cur});
    if (static_cast<int>(pool.size()) > config.pool_size) pool.pop_back();
    const double pick = std::min(rng.abs_normal(config.pool_stddev), 0.999);
    cur = pool[static_cast<size_t>(pick * static_cast<double>(pool.size()))].second;
    disrupt(cur, config.large_item_share, rng, scratch);
  }
}

void compress(Layout& best, Separator& sep, const StripSearchConfig& config, Budget& budget, Rng& rng,
              const ImprovementHook& on_improvement, SearchStats& stats) {
  QueryScratch scratch;
  const double x_lo = best.ctx().x_lo;
  Layout cur = best;
  while (!budget.exhausted()) {
    const double p = budget.progress();
    const double shrink = config.compress_shrink_start + p * (config.compress_shrink_end - config.compress_shrink_start);
    cur = best;
    const double len = best.x_hi() - x_lo;
    cur.resize(x_lo + len * (1.0 - shrink), rng.uniform(x_lo, best.x_hi()), scratch);
    sep.reseed(rng);
    if (sep.separate(cur, config.compress_separator, budget)) {
      ++stats.compress_feasible;
      fit_strip(cur, scratch);
      if (cur.x_hi() < best.x_hi()) {
        best = cur;
        if (on_improvement) on_improvement(best);
      }
    } else if (!budget.exhausted()) {
      ++stats.compress_failed;
    }
  }
}

}  // namespace tp::geometry::nesting
