// geometry/nesting/internal/strip_search.h: the improving search on the strip length: exploration
// (shrink, separate, disrupt when stuck) then compression (small shrinks at random places).
#pragma once

#include <cstdint>
#include <functional>

#include "geometry/nesting/internal/layout.h"
#include "geometry/nesting/internal/rng.h"
#include "geometry/nesting/internal/separator.h"

namespace tp::geometry::nesting {

/// Tuning of the two phases.
struct StripSearchConfig {
  double explore_shrink = 0.002;        ///< strip shrink after each feasible layout (fraction)
  int pool_size = 16;                   ///< infeasible layouts kept to restart from
  double pool_stddev = 0.25;            ///< bias of the restart choice towards the best
  double large_item_share = 0.75;       ///< "large" items: the biggest holding this share of area
  double compress_shrink_start = 5e-4;  ///< compression shrink at the start of the phase
  double compress_shrink_end = 1e-5;    ///< ... and at its end (linear in progress)
  SeparatorConfig explore_separator{200, 3, {50, 25, 3}, {}};
  SeparatorConfig compress_separator{100, 5, {50, 25, 3}, {}};
};

/// How often each phase made the shrunk strip feasible again, and how often it failed.
struct SearchStats {
  std::uint64_t explore_feasible = 0, explore_failed = 0;
  std::uint64_t compress_feasible = 0, compress_failed = 0;
};

/// Called with every better feasible layout.
using ImprovementHook = std::function<void(const Layout&)>;

/// Shrinks the strip while the separator can make the layout feasible again. `best` is feasible on
/// entry and holds the best (shortest) feasible layout on return, its strip fitted to it.
void explore(Layout& best, Separator& sep, const StripSearchConfig& config, Budget& budget, Rng& rng,
             const ImprovementHook& on_improvement, SearchStats& stats);

/// Tries many small shrinks of `best` (feasible, fitted) at random split positions, keeping each
/// that the separator makes feasible.
void compress(Layout& best, Separator& sep, const StripSearchConfig& config, Budget& budget, Rng& rng,
              const ImprovementHook& on_improvement, SearchStats& stats);

/// Swaps two large copies (and what lies under them) to leave a local minimum.
void disrupt(Layout& layout, double large_item_share, Rng& rng, QueryScratch& scratch);

/// Sets the strip length to the used length (no copy moves).
void fit_strip(Layout& layout, QueryScratch& scratch);

}  // namespace tp::geometry::nesting
