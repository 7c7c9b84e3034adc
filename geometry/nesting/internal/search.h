// geometry/nesting/internal/search.h: finding a good placement for one copy: uniform samples over
// the strip and around its current place, refined by an adaptive coordinate descent.
#pragma once

#include <limits>
#include <vector>

#include "geometry/nesting/internal/item_shape.h"
#include "geometry/nesting/internal/rng.h"

namespace tp::geometry::nesting {

/// A candidate placement and its score (lower is better; +inf: rejected).
struct Sample {
  Pose pose;
  Vec2 t;
  double score = std::numeric_limits<double>::infinity();
};

/// Scores candidate placements of one copy; owns the posed shapes it hands out.
class PlacementEvaluator {
 public:
  virtual ~PlacementEvaluator() = default;
  /// The copy's shape under `pose` (valid until the next call with another free angle).
  virtual const OrientedShape& shape(const Pose& pose) = 0;
  /// Score of the copy at (pose, t); may return +inf as soon as the score exceeds `bound`.
  virtual double evaluate(const Pose& pose, Vec2 t, double bound) = 0;
  long evaluations = 0;
};

/// How many samples to draw and refine.
struct SampleConfig {
  int container_samples = 50;  ///< uniform over the whole strip
  int focused_samples = 25;    ///< uniform around the current placement
  int refined = 3;             ///< best distinct samples refined by coordinate descent
};

/// Where and how a copy may be placed.
struct SearchSpace {
  const std::vector<Pose>* poses = nullptr;  ///< discrete poses (mirror flags only when free)
  bool free_rotation = false;
  Box2 container;        ///< region the collision outline must lie in
  double min_dim = 1;    ///< smaller side of the item's collision box, sets the step sizes
};

/// Best placement found for a copy from `current` (if given) and fresh samples.
[[nodiscard]] Sample search_placement(const SearchSpace& space, PlacementEvaluator& eval, const Sample* current,
                                      const SampleConfig& config, Rng& rng);

/// A uniformly random placement with the collision box inside `region` (box centres within
/// `focus` when given). Returns false when no pose fits.
bool random_sample(const SearchSpace& space, PlacementEvaluator& eval, const Box2* focus, Rng& rng, Sample& out);

}  // namespace tp::geometry::nesting
