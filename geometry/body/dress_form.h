// geometry/body/dress_form.h: a parametric dress form (torso, neck, arms) generated from measurements.
#pragma once

#include "geometry/body/body_mesh.h"
#include "geometry/body/measurements.h"
#include "geometry/common/error.h"

namespace tp::geometry {

/// How finely the dress form surface is sampled.
struct DressFormOptions {
  double grid_spacing_mm = 9;  ///< marching-tetrahedra grid step; the mesh has edges about this long
  bool arms = true;            ///< full arms (else the form stops at the shoulders)
};

/// One horizontal torso section: a superellipse |x/a|^n + |dz/b|^n = 1 with b = front_mm in
/// front of centre_z_mm and b = back_mm behind it.
struct TorsoSection {
  double half_width_mm = 0;
  double front_mm = 0;
  double back_mm = 0;
  double centre_z_mm = 0;
  double exponent = 2;
};

/// Heights (y, mm above the floor) and points of the dress form that drafting and placement use.
struct DressFormLandmarks {
  double bottom_y = 0, knee_y = 0, hip_y = 0, waist_y = 0, underbust_y = 0, bust_y = 0;
  double armpit_y = 0, shoulder_y = 0, nape_y = 0, neck_top_y = 0;
  double neck_radius_mm = 0;
  Vec3 shoulder_point_left;   ///< tip of the left shoulder on the surface (x > 0)
  Vec3 arm_joint_left;        ///< start of the left arm's axis
  Vec3 arm_direction_left;    ///< unit vector down the left arm
  double arm_length_mm = 0;
  double upper_arm_radius_mm = 0, wrist_radius_mm = 0;
};

/// Landmarks of the dress form for `m` (m is assumed valid).
DressFormLandmarks dress_form_landmarks(const BodyMeasurements& m);

/// The torso section at height `y_mm` (clamped to the torso's extent). Its girth matches
/// bust, underbust, waist and hips at their landmark heights.
TorsoSection dress_form_section(const BodyMeasurements& m, double y_mm);

/// The length (mm) a tape measures on the dress form from the high point of the shoulder
/// (beside the neck) over the shoulder and down the back to the waist, bridging hollows: the
/// measurement FreeSewing calls hpsToWaistBack. It is longer than `back_length_mm` (the nape
/// to the waist), by the shoulder's top and the shoulder blades.
double dress_form_hps_to_waist_back_mm(const BodyMeasurements& m);

/// Girth (mm) of a torso section: the perimeter of its superellipse.
double section_girth_mm(const TorsoSection& s);

/// Generates the dress form for `m`: a torso from below the knee to the neck base with a neck
/// and (optionally) arms hanging `arm_angle_deg` from vertical, blended smoothly, as a closed
/// mesh in the body frame (feet at y = 0). Fails with kInvalidArgument on invalid measurements.
[[nodiscard]] Result<BodyMesh> make_dress_form(const BodyMeasurements& m, const DressFormOptions& options = {});

}  // namespace tp::geometry
