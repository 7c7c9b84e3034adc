// geometry/nesting/internal/search.cpp: uniform sampling, the best-distinct-samples pool and the
// adaptive coordinate descent that refines samples into local minima.
#include "geometry/nesting/internal/search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::geometry::nesting {
namespace {

// Samples closer than this fraction of the item's smaller side (same pose) count as one.
constexpr double kUniqueSampleRatio = 0.05;
// Coordinate descent step multipliers after a success and after a failure.
constexpr double kStepGrow = 1.1;
constexpr double kStepShrink = 0.5;
// Translation steps (fractions of the item's smaller side) and rotation steps (radians) of the
// first refinement of each pooled sample and of the final refinement of the best one.
constexpr double kPreStepInit = 0.25, kPreStepLimit = 0.02;
constexpr double kFinalStepInit = 0.01, kFinalStepLimit = 0.001;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kPreRotInit = 5 * kDeg, kPreRotLimit = 1 * kDeg;
constexpr double kFinalRotInit = 0.5 * kDeg, kFinalRotLimit = 0.05 * kDeg;
/// Two poses whose angles differ by less than this (rad) have the same rotation.
constexpr double kSameAngle_rad = 1e-9;

bool same_place(const Sample& a, const Sample& b, double threshold) {
  return a.pose.index == b.pose.index && a.pose.mirror == b.pose.mirror &&
         std::fabs(a.pose.angle_rad - b.pose.angle_rad) < kSameAngle_rad && norm(a.t - b.t) < threshold;
}

// Keeps the `capacity` best samples that are pairwise distinct.
class BestSamples {
 public:
  BestSamples(int capacity, double threshold) : capacity_(capacity), threshold_(threshold) {}
  void report(const Sample& s) {
    if (!std::isfinite(s.score)) return;
    for (Sample& k : samples_) {
      if (same_place(k, s, threshold_)) {
        if (s.score < k.score) k = s;
        sort();
        return;
      }
    }
    if (static_cast<int>(samples_.size()) < capacity_) {
      samples_.push_back(s);
    } else if (s.score < samples_.back().score) {
      samples_.back() = s;
    } else {
      return;
    }
    sort();
  }
  /// Score a new sample must beat to enter the pool.
  double bound() const {
    return static_cast<int>(samples_.size()) < capacity_ ? std::numeric_limits<double>::infinity()
                                                         : samples_.back().score;
  }
  const std::vector<Sample>& samples() const { return samples_; }

 private:
  void sort() {
    std::stable_sort(samples_.begin(), samples_.end(), [](const Sample& a, const Sample& b) { return a.score < b.score; });
  }
  int capacity_;
  double threshold_;
  std::vector<Sample> samples_;
};

enum class Axis { kX, kY, kDiag, kAntiDiag, kRotate };

Axis random_axis(Rng& rng, bool rotate) {
  // Rotation gets two chances in six, as the translation axes share the rest.
  const auto r = rng.below(rotate ? 6 : 4);
  switch (r) {
    case 0: return Axis::kX;
    case 1: return Axis::kY;
    case 2: return Axis::kDiag;
    case 3: return Axis::kAntiDiag;
    default: return Axis::kRotate;
  }
}

Sample refine(Sample cur, PlacementEvaluator& eval, double step_init, double step_limit, double rot_init,
              double rot_limit, bool rotate, Rng& rng) {
  double sx = step_init, sy = step_init, sr = rot_init;
  Axis axis = random_axis(rng, rotate);
  // Bounded: each failed step halves one step size, so the loop ends after O(log) failures.
  for (int guard = 0; guard < 1000; ++guard) {
    if (sx < step_limit && sy < step_limit && (!rotate || sr < rot_limit)) break;
    Sample c[2] = {cur, cur};
    switch (axis) {
      case Axis::kX: c[0].t.x += sx; c[1].t.x -= sx; break;
      case Axis::kY: c[0].t.y += sy; c[1].t.y -= sy; break;
      case Axis::kDiag: c[0].t += Vec2{sx, sy}; c[1].t -= Vec2{sx, sy}; break;
      case Axis::kAntiDiag: c[0].t += Vec2{-sx, sy}; c[1].t += Vec2{sx, -sy}; break;
      case Axis::kRotate: c[0].pose.angle_rad += sr; c[1].pose.angle_rad -= sr; break;
    }
    for (Sample& s : c) s.score = eval.evaluate(s.pose, s.t, cur.score);
    const Sample& best = c[1].score < c[0].score ? c[1] : c[0];
    const bool better = best.score < cur.score;
    const bool worse = best.score > cur.score;
    if (!worse) cur = best;
    const double m = better ? kStepGrow : kStepShrink;
    switch (axis) {
      case Axis::kX: sx *= m; break;
      case Axis::kY: sy *= m; break;
      case Axis::kDiag:
      case Axis::kAntiDiag: sx *= std::sqrt(m); sy *= std::sqrt(m); break;
      case Axis::kRotate: sr *= m; break;
    }
    if (!better) axis = random_axis(rng, rotate);
  }
  return cur;
}

}  // namespace

bool random_sample(const SearchSpace& space, PlacementEvaluator& eval, const Box2* focus, Rng& rng, Sample& out) {
  const std::vector<Pose>& poses = *space.poses;
  if (poses.empty()) return false;
  // A few tries: a pose may not fit (e.g. a long item turned across a narrow strip).
  for (int attempt = 0; attempt < 4; ++attempt) {
    Pose pose = poses[rng.below(poses.size())];
    if (space.free_rotation) {
      pose.index = -1;
      pose.angle_rad = rng.uniform(0.0, 2 * std::numbers::pi);
    }
    const Box2& b = eval.shape(pose).box;
    double x0 = space.container.min.x - b.min.x, x1 = space.container.max.x - b.max.x;
    double y0 = space.container.min.y - b.min.y, y1 = space.container.max.y - b.max.y;
    if (focus) {
      // Box centre within the focus box.
      const Vec2 half = (b.max - b.min) * 0.5, off = b.min + half;
      x0 = std::fmax(x0, focus->min.x - off.x);
      x1 = std::fmin(x1, focus->max.x - off.x);
      y0 = std::fmax(y0, focus->min.y - off.y);
      y1 = std::fmin(y1, focus->max.y - off.y);
    }
    if (x0 > x1 || y0 > y1) continue;
    out.pose = pose;
    out.t = {rng.uniform(x0, x1), rng.uniform(y0, y1)};
    return true;
  }
  return false;
}

Sample search_placement(const SearchSpace& space, PlacementEvaluator& eval, const Sample* current,
                        const SampleConfig& config, Rng& rng) {
  BestSamples pool(std::max(1, config.refined), kUniqueSampleRatio * space.min_dim);
  if (current) {
    Sample s = *current;
    s.score = eval.evaluate(s.pose, s.t, std::numeric_limits<double>::infinity());
    pool.report(s);
    const Box2 focus = [&] {
      const Box2& b = eval.shape(current->pose).box;
      return Box2{b.min + current->t, b.max + current->t};
    }();
    for (int i = 0; i < config.focused_samples; ++i) {
      Sample f;
      if (!random_sample(space, eval, &focus, rng, f)) break;
      f.score = eval.evaluate(f.pose, f.t, pool.bound());
      pool.report(f);
    }
  }
  for (int i = 0; i < config.container_samples; ++i) {
    Sample f;
    if (!random_sample(space, eval, nullptr, rng, f)) break;
    f.score = eval.evaluate(f.pose, f.t, pool.bound());
    pool.report(f);
  }
  if (pool.samples().empty()) return current ? *current : Sample{};
  // Refine every pooled sample coarsely, then the best of them finely.
  const std::vector<Sample> starts = pool.samples();
  for (const Sample& s : starts)
    pool.report(refine(s, eval, kPreStepInit * space.min_dim, kPreStepLimit * space.min_dim, kPreRotInit,
                       kPreRotLimit, space.free_rotation, rng));
  Sample best = pool.samples().front();
  return refine(best, eval, kFinalStepInit * space.min_dim, kFinalStepLimit * space.min_dim, kFinalRotInit,
                kFinalRotLimit, space.free_rotation, rng);
}

}  // namespace tp::geometry::nesting
