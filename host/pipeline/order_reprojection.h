// host/pipeline/order_reprojection.h: an order's design, made on the base size, carried onto
// another size's body (placement "body": kept on the body in mm) or graded with it ("graded").
#pragma once

#include <string>
#include <vector>

#include "geometry/body/dress_form.h"
#include "geometry/body/measurements.h"
#include "geometry/common/vec.h"
#include "host/job/job.h"

namespace tp::host {

/// Maps points of the base size's body frame to a target size's, through the dress forms of
/// both: heights piecewise-linearly between the landmarks (knee, hip, waist, underbust, bust,
/// armpit, shoulder, nape, neck), around the body by the same direction on the torso section's
/// superellipse; off the surface by the same offset in mm ("body") or the same fraction ("graded").
class SizeMapping {
 public:
  SizeMapping(const geometry::BodyMeasurements& base, const geometry::BodyMeasurements& target, bool graded);

  [[nodiscard]] double map_height_mm(double y_mm) const;
  [[nodiscard]] geometry::Vec3 map_point(const geometry::Vec3& p_mm) const;
  /// A stroke's points: its middle point through map_point, the others at the same distances
  /// from it along the body (arc length around the torso section, height in mm) in "body"
  /// placement, so the stroke keeps its length and shape; through map_point in "graded".
  [[nodiscard]] std::vector<geometry::Vec3> map_stroke(const std::vector<geometry::Vec3>& points_mm) const;
  /// Girth of the target's torso section over the base's at base height `y_mm` (grading factor).
  [[nodiscard]] double girth_ratio(double y_mm) const;
  bool graded() const { return graded_; }
  const geometry::BodyMeasurements& base_measurements() const { return base_; }
  const geometry::BodyMeasurements& target_measurements() const { return target_; }
  const geometry::DressFormLandmarks& base_landmarks() const { return base_lm_; }
  const geometry::DressFormLandmarks& target_landmarks() const { return target_lm_; }

 private:
  geometry::BodyMeasurements base_, target_;
  geometry::DressFormLandmarks base_lm_, target_lm_;
  std::vector<double> ys_base_, ys_target_;
  bool graded_;
};

/// The centre-front bust point (on the surface, the base of "a motif at the bust point").
[[nodiscard]] geometry::Vec3 centre_front_bust_point(const geometry::BodyMeasurements& m);

/// The centre-front hip point (on the surface at the hip line: a skirt's front motif).
[[nodiscard]] geometry::Vec3 centre_front_hip_point(const geometry::BodyMeasurements& m);

/// The job's layers mapped onto the target size: planar and text centres, cylinder axes and
/// stroke points through `map`; sizes kept in mm (body) or scaled by the girth ratio (graded).
[[nodiscard]] std::vector<DesignLayerSpec> reproject_layers(const std::vector<DesignLayerSpec>& layers,
                                                            const SizeMapping& map);

}  // namespace tp::host
