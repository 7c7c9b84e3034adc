// geometry/garment/distortion.h: how far the 3D garment departs from its 2D pattern.
#pragma once

#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// One stitch: its two spans' lengths on the pattern and the sewn seam's length in 3D.
struct SeamLength {
  int stitch = 0;
  double a_mm = 0, b_mm = 0;  ///< 2D span lengths along the meshed seam (chords between seam vertices)
  double sewn_mm = 0;         ///< 3D length of the same seam vertices in the garment
  double diff = 0;            ///< max(|sewn - a|, |sewn - b|, |a - b|) / max(a, b)
  bool eased = false;         ///< marked eased or gathered (Stitch::ease_ratio > 0)
};

/// Triangles whose 2D centroid lies within this of a marked eased or gathered stitch's span (on
/// either side of it) are its eased region: their buckles and folds are the ease, reported apart.
constexpr double kEasedRegionMm = 60;

/// Distortion of a garment against its pattern. Strain of a triangle is max(|s1 - 1|, |s2 - 1|)
/// for the singular values s1, s2 of its 2D -> 3D map; mean and percentile are weighted by the
/// triangles' 2D areas, so they do not depend on mesh density. All as fractions (0.02 = 2 %).
struct DistortionReport {
  int vertices = 0;
  int triangles = 0;
  double strain_mean = 0;
  double strain_p95 = 0;
  double strain_max = 0;
  double area_change = 0;        ///< (3D area - 2D area) / 2D area, whole garment
  double seam_len_diff_max = 0;  ///< largest SeamLength::diff
  double seam_len_diff_max_plain = 0;  ///< largest SeamLength::diff of the stitches not eased
  /// Strain p95 outside and inside the eased regions (kEasedRegionMm), each weighted by 2D area
  /// (0 for an empty one), and the eased regions' share of the garment's 2D area.
  double strain_p95_plain = 0;
  double strain_p95_eased = 0;
  double eased_area_fraction = 0;
  std::vector<SeamLength> seams;
  int inside_body = 0;           ///< garment vertices with negative signed distance to the body
  double min_clearance_mm = 0;   ///< smallest signed distance of a garment vertex to the body
};

/// Measures `garment` (built from `pattern`) against its 2D pieces; body figures only when
/// `body` is given.
DistortionReport measure_distortion(const Pattern& pattern, const Garment& garment, const BodySdf* body);

}  // namespace tp::geometry
