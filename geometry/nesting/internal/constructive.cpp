// geometry/nesting/internal/constructive.cpp: left-bottom fill by sampling (the starting layout of
// the search, and the whole answer when no time is given to improve it).
#include "geometry/nesting/internal/constructive.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "geometry/nesting/internal/separator.h"

namespace tp::geometry::nesting {
namespace {

// Weight of x against y in the left-bottom score: mostly left, then low.
constexpr double kLeftWeight = 10.0;
/// Candidate positions are nudged by this fraction of the strip width (at least 1 mm), off an exact touch.
constexpr double kNudgeRel = 1e-9;

// Scores collision-free placements by how far left and low they are; +inf on collision.
class LeftBottomEvaluator : public PlacementEvaluator {
 public:
  LeftBottomEvaluator(const Layout& layout, int k, double x_limit, QueryScratch& scratch)
      : layout_(layout), k_(k), x_limit_(x_limit), scratch_(scratch), sep_(layout, k, scratch) {}
  const OrientedShape& shape(const Pose& pose) override { return sep_.shape(pose); }
  double evaluate(const Pose& pose, Vec2 t, double) override {
    ++evaluations;
    const OrientedShape& o = shape(pose);
    if (layout_.collides(k_, Candidate{&o, t}, x_limit_, scratch_)) return std::numeric_limits<double>::infinity();
    const Vec2 inner = o.poles[0].c + t;
    return kLeftWeight * (inner.x + o.box.min.x + t.x) + (inner.y + o.box.min.y + t.y);
  }

 private:
  const Layout& layout_;
  int k_;
  double x_limit_;
  QueryScratch& scratch_;
  SeparationEvaluator sep_;  // only for its posed-shape cache
};

// A collision-free place right of everything placed so far, stepping right past hazards.
bool fallback_place(Layout& layout, int k, double x_limit, QueryScratch& scratch, Sample& out) {
  const NestContext& ctx = layout.ctx();
  const int type = ctx.copy_type[k];
  const double used = layout.used_x_hi();
  const double nudge = kNudgeRel * std::max(1.0, ctx.y_hi - ctx.y_lo);
  for (size_t pi = 0; pi < ctx.poses[type].size(); ++pi) {
    const OrientedShape& o = ctx.oriented[type][pi];
    if (o.box.height() > ctx.y_hi - ctx.y_lo) continue;
    const double step = std::max(o.box.width() / 4, nudge);
    for (double x = used + nudge; x - o.box.min.x + o.box.max.x <= x_limit; x += step) {
      const Vec2 t{x - o.box.min.x, ctx.y_lo - o.box.min.y};
      if (!layout.collides(k, Candidate{&o, t}, x_limit, scratch)) {
        out.pose = ctx.poses[type][pi];
        out.t = t;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::vector<int> constructive_order(const NestContext& ctx) {
  std::vector<int> order(ctx.copy_type.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int k) {
    const ItemShape& s = ctx.shapes[ctx.copy_type[k]];
    return s.hull_area * s.diameter;
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) > key(b); });
  return order;
}

std::vector<int> construct_layout(Layout& layout, double x_limit, const SampleConfig& config, Rng& rng,
                                  const std::function<bool()>& stop) {
  QueryScratch scratch;
  std::vector<int> unplaced;
  for (int k : constructive_order(layout.ctx())) {
    if (stop()) {
      unplaced.push_back(k);
      continue;
    }
    // Sample up to one item length right of what is placed: a free place always exists there.
    SearchSpace space = search_space(layout, k);
    const Box2& b = layout.ctx().oriented[layout.ctx().copy_type[k]][0].box;
    const double reach = std::max(b.width(), b.height());
    space.container.max.x = std::min(x_limit, layout.used_x_hi() + 1.5 * reach);
    LeftBottomEvaluator eval(layout, k, x_limit, scratch);
    Sample best = search_placement(space, eval, nullptr, config, rng);
    if (!std::isfinite(best.score) && !fallback_place(layout, k, x_limit, scratch, best)) {
      unplaced.push_back(k);
      continue;
    }
    layout.place(k, best.pose, best.t, scratch, false);
  }
  return unplaced;
}

}  // namespace tp::geometry::nesting
