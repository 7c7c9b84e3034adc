// geometry/pattern/mirror.h: the mirror-image copy of a piece (the other half of a left/right pair).
#pragma once

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// The piece mirrored about its own y axis (x -> -x), outline reversed so it stays
/// counter-clockwise, with notches, darts, grain, fold line, internal lines and drill holes
/// mirrored. A 3D placement is mirrored about the body's sagittal plane (x -> -x), so the copy
/// sits on the other side of the body. `mirrored` is toggled. Edge names are kept.
Piece mirrored_piece(const Piece& piece);

}  // namespace tp::geometry
