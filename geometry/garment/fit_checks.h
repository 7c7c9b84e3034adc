// geometry/garment/fit_checks.h: checks that a sewn garment is really sewn, untangled and on the body.
#pragma once

#include <string>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Limits of the fit checks; a garment beyond any of them fails. Fractions are 0..1.
struct FitLimits {
  double max_stitch_gap_mm = 2;           ///< largest distance between a stitch's two sides before merging
  double max_self_intersections = 0.002;  ///< intersecting triangle pairs / triangles
  double max_inside_body = 0.002;         ///< vertices inside the body / vertices
  /// Triangles crossing the body's surface / triangles. 1 (not limited) by default: contact is
  /// per vertex, so a mesh coarser than the body's curvature crosses it between vertices (the
  /// figure is reported; a job may limit it).
  double max_body_crossings = 1;
  double max_off_body = 0.05;             ///< area farther than off_body_distance_mm / area
  double off_body_distance_mm = 150;
};

/// Figures of the checks and what failed. Views are the preview to look at: "front", "side", "back".
struct FitReport {
  int stitches = 0;                  ///< stitches measured
  double stitch_gap_max_mm = 0;      ///< over every sewn vertex pair of every stitch
  double stitch_gap_p95_mm = 0;
  int worst_stitch = -1;             ///< the stitch holding the largest gap
  int triangles = 0;
  int self_intersections = 0;        ///< triangle pairs that intersect and share no vertex
  int vertices = 0;
  int inside_body = 0;               ///< vertices with negative signed distance to the body
  /// Triangles crossing the body's surface: a body feature sharper than the mesh poking through
  /// the cloth between vertices that are all outside it.
  int body_crossings = 0;
  double body_distance_p50_mm = 0;   ///< unsigned distance of the vertices to the body surface
  double body_distance_p95_mm = 0;
  double off_body = 0;               ///< area fraction farther than off_body_distance_mm from the body
  /// Pieces no stitch joins to another piece (a pocket bag, a label): printed flat, left out of
  /// the body and self-intersection checks.
  std::vector<int> unsewn_pieces;
  bool pass = true;
  /// One per failed check: "stitch_gap", "self_intersections", "inside_body", "body_crossings"
  /// or "off_body"; a sentence naming the figure, the limit and the worst stitch or piece; the
  /// preview to look at.
  struct Failure {
    std::string check;
    std::string message;
    std::string view;
  };
  std::vector<Failure> failures;
};

/// Intersecting triangle pairs of the garment that share no vertex (CGAL box intersection for
/// candidates, exact predicates for the test); degenerate triangles are skipped. Optionally the
/// count per piece (triangles of that piece in such a pair), in pattern order.
/// Pieces flagged in `skip` (by index) are left out.
int count_self_intersections(const Garment& garment, std::vector<int>* per_piece = nullptr,
                             const std::vector<bool>* skip = nullptr);

/// Triangles of the garment that intersect a triangle of `body` (CGAL box intersection for
/// candidates, exact predicates for the test); degenerate triangles are skipped. Optionally the
/// count per piece, in pattern order; pieces flagged in `skip` are left out.
int count_body_crossings(const Garment& garment, const BodyMesh& body, std::vector<int>* per_piece = nullptr,
                         const std::vector<bool>* skip = nullptr);

/// Runs every check on the final `garment` of `pattern`. `stitch_gaps_mm` holds, per stitch,
/// the distances between its two sides' vertex pairs at the end of sewing (SewStats; empty
/// for a garment not sewn here: then the gap check is skipped). Body checks need `body`;
/// without it only gaps and self-intersections are checked. Pieces no stitch joins to another
/// piece are listed in unsewn_pieces and left out.
FitReport check_fit(const Pattern& pattern, const Garment& garment, const BodySdf* body,
                    const std::vector<std::vector<double>>& stitch_gaps_mm, const FitLimits& limits = {});

}  // namespace tp::geometry
