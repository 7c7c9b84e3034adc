// geometry/nesting/strip_nester.h: the strip-packing engine: irregular polygons on a strip of fixed
// width, minimising the used length (constructive placement, then overlap-minimising search).
//
// Strip frame (the ESICUP convention): the strip runs along +x from x = 0, its fixed width spans
// y in [0, width]. A placement maps an item's own coordinates by mirror x -> -x (if mirrored),
// then a counter-clockwise rotation about the origin, then a translation.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// One allowed pose of an item: mirror x -> -x first (if `mirror`), then rotate.
struct StripPose {
  double rotation_deg = 0;  ///< counter-clockwise
  bool mirror = false;
};

/// An item type to nest, `demand` copies of it.
struct StripItem {
  int id = 0;                    ///< caller's id, copied to StripPlacement::item_id
  std::string name;              ///< for messages; "item <index> (id <id>)" when empty
  Polygon shape;                 ///< simple polygon in the item's own frame (any orientation)
  int demand = 1;                ///< copies to place
  /// Allowed discrete poses. With `free_rotation`, only their mirror flags count (any angle).
  std::vector<StripPose> poses{StripPose{}};
  bool free_rotation = false;
};

/// A strip-packing instance.
struct StripProblem {
  std::string name;
  double width = 0;                 ///< fixed strip width (along y), > 0
  std::vector<StripItem> items;
  std::vector<Polygon> hazards;     ///< zones no item may overlap (fabric defects), strip frame
};

/// How to search.
struct StripOptions {
  double gap = 0;             ///< minimum distance between items, and between items and hazards
  double edge_margin = 0;     ///< minimum distance from items to y = 0 and y = width
  double start_margin = 0;    ///< minimum distance from items to x = 0
  /// Items are only placed with x <= length_limit - (gap/2); copies that do not fit are returned
  /// in StripSolution::unplaced (0 = no limit, every copy is placed).
  double length_limit = 0;
  /// Wall-clock budget; the best solution so far is returned. 0 with a work_limit: no time
  /// limit at all (the clock is never read).
  double time_limit_s = 10;
  /// Work budget in separator iterations (0 = none). With only this budget (time_limit_s 0),
  /// the result is a function of the problem, the options and the seed alone, whatever the load.
  std::uint64_t work_limit = 0;
  std::uint64_t seed = 0;
  int threads = 2;            ///< OS threads running the workers (does not change the result)
  int workers = 2;            ///< parallel search workers per iteration (changes the result)
  bool improve = true;        ///< false: constructive placement only
  double explore_fraction = 0.8;  ///< share of the budget for exploration, the rest compresses
  /// Largest area a conservative simplification may add to an item outline, as a fraction of
  /// its area (never removes material: the simplified outline contains the original).
  double simplify_tolerance = 0.001;
  /// Called (from the calling thread) whenever a better feasible solution is found.
  std::function<void(double length, double density, double seconds)> on_improvement;
  /// With a work_limit: called (from the calling thread) with the separator iterations done and
  /// the work_limit, each time another whole percent of the limit is done (at most 100 calls a
  /// run, never per iteration). It only observes: the layout is the same with or without it.
  std::function<void(std::uint64_t done, std::uint64_t total)> on_work;
};

/// Where one copy of an item lies.
struct StripPlacement {
  int item = 0;              ///< index into StripProblem::items
  int item_id = 0;           ///< StripItem::id of that item
  double rotation_deg = 0;   ///< counter-clockwise, applied after the mirror
  bool mirror = false;       ///< x -> -x in the item's frame, applied first
  Vec2 translation;
};

/// The best feasible layout found.
struct StripSolution {
  std::vector<StripPlacement> placements;
  std::vector<int> unplaced;  ///< item indices (one per copy) that did not fit in length_limit
  double length = 0;          ///< largest x of any placed item (original outline)
  double density = 0;         ///< placed item area / (width * length), 0..1
  double seconds = 0;         ///< wall-clock time spent
  std::uint64_t iterations = 0;  ///< separator iterations run
  std::uint64_t evaluations = 0; ///< candidate placements evaluated by the search
  double constructive_length = 0;  ///< length after the constructive placement
  /// Shrinks the search made feasible again / gave up on, in exploration and in compression.
  std::uint64_t explore_feasible = 0, explore_failed = 0, compress_feasible = 0, compress_failed = 0;
};

/// Nests every copy of every item on the strip.
///
/// Fails with kInvalidArgument when the width or an option is out of range, kInvalidPattern when
/// an item is not a simple polygon with positive area (naming the item), kNesting when an item
/// cannot fit the strip width in any allowed pose, and kCancelled when `cancel` fires before a
/// first complete layout exists (after that, cancelling returns the best layout so far).
[[nodiscard]] Result<StripSolution> nest_strip(const StripProblem& problem, const StripOptions& options,
                                               const CancelToken& cancel = {});

/// Transforms an item outline by a placement: mirror, rotate, translate (the output convention).
[[nodiscard]] Polygon place_polygon(const Polygon& shape, const StripPlacement& placement);

}  // namespace tp::geometry
