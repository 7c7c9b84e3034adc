// geometry/nesting/internal/layout.h: a layout of item copies on the strip with its collision
// tracker (pairwise overlap losses and guided-local-search weights).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/nesting/internal/item_shape.h"
#include "geometry/nesting/internal/overlap.h"

namespace tp::geometry::nesting {

/// Immutable data of one nesting run, shared by all workers.
struct NestContext {
  std::vector<ItemShape> shapes;                       ///< per item type
  std::vector<std::vector<Pose>> poses;                ///< allowed discrete poses per type
  std::vector<std::vector<OrientedShape>> oriented;    ///< shapes[t] under poses[t][i]
  std::vector<std::vector<double>> pose_degrees;       ///< poses[t][i] as the caller gave it, degrees
  std::vector<bool> free_rotation;                     ///< per type: any angle (mirrors of poses)
  std::vector<int> copy_type;                          ///< item type of each copy
  /// Hazard collision shapes (already grown) in strip coordinates, with their poles.
  std::vector<ItemShape> hazards;
  double x_lo = 0, y_lo = 0, y_hi = 0;                 ///< container bounds for collision outlines
};

/// One copy (or hazard) where it lies: its collision shape translated into strip coordinates.
struct Placed {
  bool present = false;
  Pose pose;
  Vec2 t;
  std::vector<Vec2> pts;
  std::vector<Circle> poles;
  PoleSoA pole_soa;            ///< the same poles, for the overlap proxy
  Box2 box;
  double hull_area = 0;
  double diameter = 0;
  double original_max_x = 0;
  double original_min_x = 0;
};

/// Loss and weight of one pair (or of an item against the container).
struct PairEntry {
  double loss = 0;
  double weight = 1;
};

/// Reusable buffers for collision queries (one per thread of work).
struct QueryScratch {
  std::vector<Vec2> pts;
  std::vector<int> edges_a, edges_b;
  OrientedShape free_pose;  ///< the candidate's shape when its angle is free
};

/// A candidate placement of one copy, evaluated against a layout.
struct Candidate {
  const OrientedShape* shape = nullptr;
  Vec2 t;
};

/// Guided-local-search weight update (multiplicative increase on colliding pairs, decay else).
struct GlsWeights {
  double min_increase = 1.2;
  double max_increase = 2.0;
  double decay = 0.95;
};

/// All copies of a run on a strip of length `x_hi` (collision-outline bound), plus the tracker.
class Layout {
 public:
  Layout() = default;
  explicit Layout(const NestContext* ctx, double x_hi);

  const NestContext& ctx() const { return *ctx_; }
  int size() const { return static_cast<int>(items_.size()); }
  const Placed& item(int k) const { return items_[k]; }
  double x_hi() const { return x_hi_; }

  /// The shape of copy `k` under `pose` (cached for discrete poses, built in `scratch` otherwise).
  const OrientedShape& shape_for(int k, const Pose& pose, QueryScratch& scratch) const;

  /// Places (or moves) copy `k`; with `track` the tracker row of `k` is recomputed.
  void place(int k, const Pose& pose, Vec2 t, QueryScratch& scratch, bool track);
  /// Removes copy `k` from the layout (constructive phase only; no tracking).
  void remove(int k);

  /// Weighted loss of copy `k` at a candidate placement (itself excluded), or +inf as soon as it
  /// exceeds `bound`. 0 means the candidate collides with nothing.
  double weighted_loss(int k, const Candidate& c, double bound, QueryScratch& scratch) const;
  /// True when a candidate placement of copy `k` collides with any present copy, hazard, or the
  /// container bounded by `x_limit`.
  bool collides(int k, const Candidate& c, double x_limit, QueryScratch& scratch) const;

  /// Changes the strip length: copies whose box centre lies right of `split_x` shift by the
  /// change; the tracker is rebuilt with unit weights.
  void resize(double new_x_hi, double split_x, QueryScratch& scratch);
  /// Recomputes every tracker entry from scratch (weights kept).
  void rebuild_tracker(QueryScratch& scratch);
  /// Copies positions and losses of `other` (same run), keeping this layout's weights.
  void restore_keep_weights(const Layout& other);

  double total_loss() const;
  double total_weighted_loss() const;
  double item_loss(int k) const;
  void update_weights(const GlsWeights& w);

  /// Largest x of any present collision outline / original outline.
  double used_x_hi() const;
  double used_original_x_hi() const;

 private:
  /// Loss of a shape against a placed copy (0: no collision); +inf once it exceeds `limit`.
  double pair_loss(const Vec2* pts, int n, const Box2& box, Vec2 inner, const std::vector<Circle>& poles,
                   Vec2 pole_shift, double hull_a, double diam_a, const Placed& other, QueryScratch& s,
                   double limit = kUnbounded) const;
  static constexpr double kUnbounded = 1e300;
  double container_loss(const Box2& box, double hull_area) const;
  void recompute_row(int k, QueryScratch& scratch);
  PairEntry& pair(int i, int j) { return pairs_[static_cast<size_t>(i) * cols_ + j]; }
  const PairEntry& pair(int i, int j) const { return pairs_[static_cast<size_t>(i) * cols_ + j]; }

  const NestContext* ctx_ = nullptr;
  double x_hi_ = 0;
  void sync_box(int k);

  std::vector<Placed> items_;
  /// Boxes of the copies, contiguous for the broad phase; absent copies get an empty box.
  std::vector<Box2> boxes_;
  std::vector<Placed> hazards_;
  int cols_ = 0;                    ///< copies + hazards
  std::vector<PairEntry> pairs_;    ///< row per copy; columns: copies then hazards
  std::vector<PairEntry> container_;
};

/// Builds a Placed from a posed shape and translation.
void make_placed(const OrientedShape& o, const ItemShape& s, const Pose& pose, Vec2 t, Placed& out);

}  // namespace tp::geometry::nesting
