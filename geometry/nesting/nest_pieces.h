// geometry/nesting/nest_pieces.h: marker planning for a garment job: pattern pieces with their
// grain, mirror and quantity rules nested on the fabric roll, split into markers of bounded
// length, around fabric defects.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/nesting/marker.h"

namespace tp::geometry {

/// Which turns a piece may take on the roll, relative to its grain line lying along the roll.
enum class PieceRotation {
  kOneWay,        ///< grain along +y only: one-way prints, nap, pile
  kGrainBothWays, ///< grain along +y or -y (0 or 180 degrees): the default
  kQuarterTurns,  ///< grain along or across the roll (90-degree steps)
  kFree,          ///< any angle (knits and prints without a grain rule)
};

/// Whether a piece may be cut mirrored.
enum class PieceMirror {
  kNever,    ///< as drawn
  kAllowed,  ///< each copy may be mirrored or not (symmetric pieces, reversible fabric)
  kPairs,    ///< `quantity` left/right pairs: one copy as drawn and one mirrored per pair
};

/// One pattern piece to cut.
struct NestItem {
  int piece = 0;               ///< index into Pattern::pieces, copied to PiecePlacement::piece
  std::string name;            ///< for messages ("front", "sleeve_l")
  Polygon outline_mm;          ///< cut outline (seam allowance included), piece-local mm
  int quantity = 1;            ///< copies (pairs with PieceMirror::kPairs)
  PieceRotation rotation = PieceRotation::kGrainBothWays;
  PieceMirror mirror = PieceMirror::kNever;
  Vec2 grain{0, 1};            ///< warp direction in piece-local coordinates; laid along the roll
};

/// The fabric and the search budget.
struct NestOptions {
  double fabric_width_mm = 0;       ///< usable roll width
  double gap_mm = 0;                ///< minimum distance between pieces, and to defects
  double selvedge_margin_mm = 0;    ///< minimum distance from pieces to both fabric edges
  double end_margin_mm = 0;         ///< free fabric before the first and after the last piece
  /// Zones to avoid, roll frame (x across, y along the roll from the start of the fabric).
  std::vector<Polygon> defects_mm;
  double max_length_mm = 0;         ///< longest marker (0: one marker of any length)
  double time_limit_s = 5;          ///< search time for all markers together (0 with work_limit: none)
  /// Separator iterations for all markers together (0: none). With time_limit_s 0 this is the
  /// only budget and the markers depend on the pieces, the options and the seed alone.
  std::uint64_t work_limit = 0;
  std::uint64_t seed = 0;
  int threads = 2;
  int workers = 2;
  /// With a work_limit: called (from the calling thread) with the separator iterations done on
  /// all markers so far and the work_limit, at each whole percent of a marker's share (a bounded
  /// number of calls). It only observes: the markers are the same with or without it.
  std::function<void(std::uint64_t done, std::uint64_t total)> on_work;
};

/// What the search spent, per marker (same order as the markers).
struct NestStats {
  std::vector<std::uint64_t> iterations;  ///< separator iterations
  std::vector<double> seconds;            ///< wall-clock time
};

/// Nests all pieces into one or more markers laid one after the other on the roll (marker k
/// starts where marker k-1 ends, `roll_start_mm`). Placements are in the marker's frame (y from
/// its start); every piece outline maps by PiecePlacement::piece_to_roll.
///
/// Fails with kInvalidArgument for out-of-range options, kInvalidPattern naming the piece whose
/// outline is not a simple polygon or whose grain is zero, kNesting when a piece fits neither the
/// width nor the maximum length in any allowed orientation, kCancelled when cancelled before a
/// first layout exists.
[[nodiscard]] Result<std::vector<Marker>> nest_pieces(const std::vector<NestItem>& items, const NestOptions& options,
                                                      const CancelToken& cancel = {}, NestStats* stats = nullptr);

/// Roll rotations (degrees, in [0, 360)) that lay `grain` (piece-local, y up) along roll +y under
/// a rule, after the face-up flip y -> -y and, for the `mirrored` piece, x -> -x.
[[nodiscard]] std::vector<double> grain_rotations_deg(Vec2 grain, PieceRotation rule, bool mirrored);

}  // namespace tp::geometry
