// geometry/nesting/internal/separator.h: overlap minimisation by guided local search: colliding
// copies are moved to their least-weighted-loss place, by several workers in parallel, until the
// layout is feasible or the search stalls.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "geometry/common/cancel.h"
#include "geometry/common/thread_pool.h"
#include "geometry/nesting/internal/layout.h"
#include "geometry/nesting/internal/rng.h"
#include "geometry/nesting/internal/search.h"

namespace tp::geometry::nesting {

/// Time, work and cancellation limits of a phase. Without `timed`, no clock is read: the phase
/// ends on its work limit (or cancellation) alone, so its result does not depend on CPU load.
struct Budget {
  std::chrono::steady_clock::time_point start, deadline;
  std::uint64_t work_limit = 0;  ///< separator iterations; 0 = unlimited
  std::uint64_t* work_done = nullptr;
  std::uint64_t work_start = 0;
  const CancelToken* cancel = nullptr;
  bool timed = true;  ///< false: `start` and `deadline` are ignored
  /// Called after every separator iteration (empty: nothing); it only observes.
  const std::function<void()>* on_work = nullptr;

  bool out_of_time() const {
    return (cancel && cancel->cancelled()) || (timed && std::chrono::steady_clock::now() >= deadline);
  }
  bool exhausted() const { return out_of_time() || (work_limit && *work_done - work_start >= work_limit); }
  /// Fraction of the phase used, the larger of time and work.
  double progress() const;
};

/// Limits of one separation attempt.
struct SeparatorConfig {
  int iter_no_improve_limit = 200;
  int strike_limit = 3;
  SampleConfig samples;
  GlsWeights gls;
};

/// Moves colliding copies until none collide.
class Separator {
 public:
  Separator(int workers, ThreadPool* team);

  /// New worker random streams derived from `rng` (after the strip length changes).
  void reseed(Rng& rng);
  /// Separates `layout` in place. True when it ends feasible (no collision); otherwise the layout
  /// holds the least-loss state found. Counts one unit of work per iteration.
  bool separate(Layout& layout, const SeparatorConfig& config, Budget& budget);
  /// Moves one copy to the best place found for it in `layout` (the disruption step uses this).
  void move_one(Layout& layout, int k, const SampleConfig& samples, Rng& rng);

  long evaluations() const;

 private:
  struct Worker {
    Layout layout;
    Rng rng;
    QueryScratch scratch;
    long evaluations = 0;
  };
  void move_items(Worker& w, const SampleConfig& samples, const Budget& budget);
  void move_items_multi(Layout& master, const SampleConfig& samples, const Budget& budget);

  ThreadPool* team_;
  std::vector<Worker> workers_;
  QueryScratch scratch_;
  long own_evaluations_ = 0;
};

/// The search space of copy `k` in `layout`.
[[nodiscard]] SearchSpace search_space(const Layout& layout, int k);

/// Scores placements by the weighted overlap loss of copy `k` (0 = collides with nothing).
class SeparationEvaluator : public PlacementEvaluator {
 public:
  SeparationEvaluator(const Layout& layout, int k, QueryScratch& scratch) : layout_(layout), k_(k), scratch_(scratch) {}
  const OrientedShape& shape(const Pose& pose) override;
  double evaluate(const Pose& pose, Vec2 t, double bound) override;

 private:
  const Layout& layout_;
  int k_;
  QueryScratch& scratch_;
  OrientedShape free_;
  double free_angle_ = 1e300;
  bool free_mirror_ = false;
};

}  // namespace tp::geometry::nesting
