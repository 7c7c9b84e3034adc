// geometry/pattern/copies.cpp: expanding quantities and mirrored pairs into physical pieces.
#include "geometry/pattern/copies.h"

#include "geometry/pattern/mirror.h"

namespace tp::geometry {

std::vector<Piece> expand_copies(const Piece& drafted, int quantity, bool mirror_pairs, DraftedSide side) {
  std::vector<Piece> out;
  if (quantity < 1) return out;
  Piece base = drafted;
  if (base.source_piece.empty()) base.source_piece = drafted.name;
  if (quantity == 1) {
    out.push_back(std::move(base));
    return out;
  }
  if (mirror_pairs && quantity % 2 == 0) {
    const char* drafted_suffix = side == DraftedSide::kLeft ? "_l" : "_r";
    const char* mirror_suffix = side == DraftedSide::kLeft ? "_r" : "_l";
    Piece mirror = mirrored_piece(base);
    const int pairs = quantity / 2;
    for (int k = 1; k <= pairs; ++k) {
      std::string n = pairs == 1 ? "" : std::to_string(k);
      Piece a = base, b = mirror;
      a.name = drafted.name + drafted_suffix + n;
      b.name = drafted.name + mirror_suffix + n;
      out.push_back(std::move(a));
      out.push_back(std::move(b));
    }
    return out;
  }
  for (int k = 1; k <= quantity; ++k) {
    Piece a = base;
    a.name = drafted.name + "_" + std::to_string(k);
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace tp::geometry
