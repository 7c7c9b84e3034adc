// geometry/design/sample_designs.h: the print designs of the paper's experiments (section 4.1)
// for the sample garments, made from procedural textures.
#pragma once

#include <string_view>

#include "geometry/common/error.h"
#include "geometry/design/design.h"
#include "geometry/garment/garment.h"

namespace tp::geometry {

/// The paper's design for a sample garment:
///  - "skirt8": cylindrical projection of a marbling texture;
///  - "dress", "blouse": cylindrical projection of marbling with a planar placement motif on the front;
///  - "simple_top": brush strokes painted on the 3D surface (rings around the body and a diagonal
///    sweep crossing the side seams);
///  - anything else: the skirt's cylindrical marbling.
/// Sizes are relative to the garment (cylinder fitted around it).
Design sample_design(std::string_view garment_name, const Garment& garment);

}  // namespace tp::geometry
