// geometry/garment/role_placement.h: placements for pieces that come without one, from their role and the body's landmarks.
#pragma once

#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Heights and extents of a standing body found from horizontal slices of its signed distance
/// (mm, body frame). Arms are found as the first solid beyond the torso's side at two slices
/// below the shoulders; their centres give the arm's axis.
struct BodyLandmarks {
  Vec3 axis;                   ///< a point of the torso's vertical axis (y = 0)
  double top_y = 0;            ///< highest point
  double shoulder_y = 0;       ///< where the slice first widens from the neck to the shoulders
  double waist_y = 0;          ///< narrowest slice 300..520 mm below the shoulders
  double hip_y = 0;            ///< widest slice 150..250 mm below the waist
  double front_z = 0, back_z = 0;  ///< torso surface in front and behind the axis at the bust
  double side_x = 0;           ///< torso half width at the bust
  double waist_front_z = 0, waist_back_z = 0;  ///< the same at the waist
  Vec3 shoulder_l, shoulder_r;  ///< shoulder points (+x is the wearer's left)
  Vec3 arm_dir_l{0.7, -0.7, 0}, arm_dir_r{-0.7, -0.7, 0};  ///< unit, down the arm's axis
  Vec3 arm_top_l, arm_top_r;  ///< where the arm's axis passes the shoulder point (a sleeve cap's top)
};

/// Landmarks of `body` (any body the project sews on: dress form, scanned or average body).
BodyLandmarks find_landmarks(const BodySdf& body);

/// One placement per piece: the piece's own when it has one, else one from its role (Piece::role;
/// front, back, sleeve, waistband, collar, cuff, pocket, yoke, hood, facing, placket): fronts
/// face forward just outside the torso, backs face backward (mirror copies side by side at the
/// centre line), each hanging from the shoulders, or from the waist for lower garments (a
/// pattern with a waistband or skirt, trouser or pant pieces and no sleeve); sleeves lie along
/// their arm, cap at the shoulder, one tube radius outside the arm's axis so that rolling them
/// into tubes puts them round it; waistbands at the waist in front. Pieces of unknown role go in
/// front. Deterministic.
std::vector<Placement3d> role_placements(const Pattern& pattern, const BodySdf& body);

}  // namespace tp::geometry
