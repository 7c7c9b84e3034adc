// geometry/garment/align_to_body.h: bringing a pattern placed in another body's frame onto the job's body.
#pragma once

#include <string>

#include "geometry/body/body_sdf.h"
#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// What align_to_body did to the placements.
struct BodyAlignment {
  bool moved = false;        ///< placements were changed
  bool turned = false;       ///< turned 180 deg about the vertical (fronts were behind the body)
  Vec3 offset_mm;            ///< translation applied (after the turn)
  std::string garment_kind;  ///< "lower" (from the waist) or "upper" (from the shoulders)
  std::string reason;        ///< why, for the report ("placed pieces 1012 mm below the body's waist ...")
};

/// Waist and shoulder heights of a body (mm, body frame), from its bounds: 0.62 and 0.82 of its
/// height above its lowest point (the dress form's and GarmentCode's bodies' proportions).
double waist_height_mm(const Box3& body_box);
double shoulder_height_mm(const Box3& body_box);

/// Checks that the placed pieces of `pattern` surround `body`: their bounds contain the body's
/// vertical axis and overlap its height by at least half their own height, and front pieces
/// (role "front") are in front of back pieces. When not (a pattern placed around another body,
/// a mirrored axis), the placements are turned and moved so the pieces' bounds are centred on
/// the body's axis with their top at the waist (lower garments: skirts, trousers, waistbands by
/// piece name or role) or just above the shoulders (others). Pieces without a placement are left
/// alone; a pattern without placements is not changed. Fails (kInvalidPattern, naming both
/// sizes) when the placed pieces are over 2.5 times the body's height or under 2 % of it (wrong
/// units), since no move can fix that.
[[nodiscard]] Result<BodyAlignment> align_to_body(Pattern& pattern, const BodySdf& body);

}  // namespace tp::geometry
