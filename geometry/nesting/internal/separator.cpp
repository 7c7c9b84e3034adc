// geometry/nesting/internal/separator.cpp: the thread team, the separation evaluator and the
// guided-local-search separation loop with its parallel workers.
#include "geometry/nesting/internal/separator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/common/tolerances.h"

namespace tp::geometry::nesting {
namespace {

// A new least loss resets the stall counter only when it beats the old one by this factor.
constexpr double kSubstantialImprovement = 0.98;

}  // namespace

double Budget::progress() const {
  using namespace std::chrono;
  double p = 0;
  if (timed) {
    const double total = duration<double>(deadline - start).count();
    p = total > 0 ? duration<double>(steady_clock::now() - start).count() / total : 1.0;
  }
  if (work_limit) p = std::max(p, static_cast<double>(*work_done - work_start) / static_cast<double>(work_limit));
  return std::clamp(p, 0.0, 1.0);
}

const OrientedShape& SeparationEvaluator::shape(const Pose& pose) {
  if (pose.index >= 0) return layout_.ctx().oriented[layout_.ctx().copy_type[k_]][pose.index];
  if (pose.angle_rad != free_angle_ || pose.mirror != free_mirror_) {
    free_ = orient(layout_.ctx().shapes[layout_.ctx().copy_type[k_]], pose);
    free_angle_ = pose.angle_rad;
    free_mirror_ = pose.mirror;
  }
  return free_;
}

double SeparationEvaluator::evaluate(const Pose& pose, Vec2 t, double bound) {
  ++evaluations;
  const Candidate c{&shape(pose), t};
  return layout_.weighted_loss(k_, c, bound, scratch_);
}

SearchSpace search_space(const Layout& layout, int k) {
  const NestContext& ctx = layout.ctx();
  const int type = ctx.copy_type[k];
  SearchSpace s;
  s.poses = &ctx.poses[type];
  s.free_rotation = ctx.free_rotation[type];
  s.container = Box2{{ctx.x_lo, ctx.y_lo}, {layout.x_hi(), ctx.y_hi}};
  const Box2& b = ctx.oriented[type][0].box;
  s.min_dim = std::max(kMinDivisor, std::min(b.width(), b.height()));
  return s;
}

Separator::Separator(int workers, ThreadPool* team) : team_(team) { workers_.resize(std::max(1, workers)); }

void Separator::reseed(Rng& rng) {
  for (Worker& w : workers_) w.rng = Rng(rng.next());
}

long Separator::evaluations() const {
  long n = own_evaluations_;
  for (const Worker& w : workers_) n += w.evaluations;
  return n;
}

void Separator::move_one(Layout& layout, int k, const SampleConfig& samples, Rng& rng) {
  SeparationEvaluator eval(layout, k, scratch_);
  const Placed& p = layout.item(k);
  const Sample current{p.pose, p.t, 0};
  const Sample best = search_placement(search_space(layout, k), eval, &current, samples, rng);
  own_evaluations_ += eval.evaluations;
  layout.place(k, best.pose, best.t, scratch_, true);
}

void Separator::move_items(Worker& w, const SampleConfig& samples, const Budget& budget) {
  Layout& layout = w.layout;
  std::vector<int> colliding;
  for (int k = 0; k < layout.size(); ++k)
    if (layout.item(k).present && layout.item_loss(k) > 0) colliding.push_back(k);
  // Fisher-Yates with the worker's own stream: each worker tries its own order.
  for (size_t i = colliding.size(); i > 1; --i) std::swap(colliding[i - 1], colliding[w.rng.below(i)]);
  for (int k : colliding) {
    if (budget.out_of_time()) return;
    if (!(layout.item_loss(k) > 0)) continue;
    SeparationEvaluator eval(layout, k, w.scratch);
    const Placed& p = layout.item(k);
    const Sample current{p.pose, p.t, 0};
    const Sample best = search_placement(search_space(layout, k), eval, &current, samples, w.rng);
    w.evaluations += eval.evaluations;
    layout.place(k, best.pose, best.t, w.scratch, true);
  }
}

void Separator::move_items_multi(Layout& master, const SampleConfig& samples, const Budget& budget) {
  for (Worker& w : workers_) w.layout = master;
  team_->parallel_for(static_cast<int>(workers_.size()), [&](int i, int) { move_items(workers_[i], samples, budget); });
  // Keep the worker with the least weighted loss; ties go to the lowest index.
  size_t best = 0;
  double best_loss = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < workers_.size(); ++i) {
    const double l = workers_[i].layout.total_weighted_loss();
    if (l < best_loss) {
      best_loss = l;
      best = i;
    }
  }
  master = workers_[best].layout;
}

bool Separator::separate(Layout& layout, const SeparatorConfig& config, Budget& budget) {
  Layout best = layout;
  double min_loss = layout.total_loss();
  if (min_loss == 0) return true;
  int strikes = 0;
  while (strikes < config.strike_limit && !budget.exhausted()) {
    int no_improve = 0;
    const double strike_start_loss = layout.total_loss();
    while (no_improve < config.iter_no_improve_limit && !budget.exhausted()) {
      move_items_multi(layout, config.samples, budget);
      ++*budget.work_done;
      if (budget.on_work) (*budget.on_work)();
      const double loss = layout.total_loss();
      if (loss == 0) return true;
      if (loss < min_loss) {
        if (loss < min_loss * kSubstantialImprovement) no_improve = 0;
        best.restore_keep_weights(layout);
        min_loss = loss;
      } else {
        ++no_improve;
      }
      layout.update_weights(config.gls);
    }
    if (strike_start_loss * kSubstantialImprovement <= min_loss) {
      ++strikes;
    } else {
      strikes = 0;
    }
    layout.restore_keep_weights(best);
  }
  return false;
}

}  // namespace tp::geometry::nesting
