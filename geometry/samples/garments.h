// geometry/samples/garments.h: the four sample garments of the paper's Table 2, drafted and sewn.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/body/measurements.h"
#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/sewing/sew_garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::samples {

/// Names of the sample garments: "simple_top", "blouse", "dress", "skirt8".
const std::vector<std::string>& garment_names();

/// Drafts the named garment for `m`; Pattern::size is set to `size_label`. Pieces carry
/// named edges, notches, grain lines, roles and 3D placements on the dress form of `m`;
/// stitches cover every seam and dart. Fails with kInvalidArgument for an unknown name or
/// invalid measurements.
[[nodiscard]] Result<Pattern> draft_garment(std::string_view name, const BodyMeasurements& m, const std::string& size_label);

/// A sample garment sewn on its dress form.
struct SampleGarment {
  Pattern pattern;
  Garment garment;
  BodyMeasurements measurements;
  std::shared_ptr<const BodySdf> body;  ///< the dress form as a collision object (mesh inside)
  SewStats stats;
};

/// Drafts the named garment for `size` (see parse_size: "M", "bust=940,...", "L:hips=1120"),
/// generates the dress form for the same measurements and sews the garment on it.
[[nodiscard]] Result<SampleGarment> make_garment(std::string_view name, std::string_view size,
                                                 const SewOptions& options = {});

/// The dress form for `m` as a collision object.
[[nodiscard]] Result<std::shared_ptr<const BodySdf>> make_dress_form_sdf(const BodyMeasurements& m);

}  // namespace tp::geometry::samples
