// geometry/pattern/copies.h: a pattern piece cut N times ("cut 2, mirrored") as physical pieces.
#pragma once

#include <vector>

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Which side of the body the piece as drafted is for (convention only; names the copies).
enum class DraftedSide { kLeft, kRight };

/// The physical pieces cut from one pattern piece.
/// - quantity 1: the piece itself.
/// - mirror_pairs and an even quantity: pairs, the drafted piece and its mirror image
///   (mirrored_piece), named "<name>_l"/"<name>_r" (for `side` the drafted one), or
///   "<name>_l1", "<name>_r1", "<name>_l2", ... for more than one pair.
/// - otherwise: identical copies "<name>_1" .. "<name>_N".
/// Every copy has source_piece = the drafted piece's name (or its own source_piece if set).
/// A quantity below 1 gives no pieces.
std::vector<Piece> expand_copies(const Piece& drafted, int quantity, bool mirror_pairs,
                                 DraftedSide side = DraftedSide::kLeft);

}  // namespace tp::geometry
