// geometry/sewing/internal/cloth_model.h: the cloth the XPBD solver steps: masses, per-triangle
// rest shapes, bending stencils and edges, built once from a sewn garment.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/garment/garment.h"
#include "geometry/sewing/cloth_material.h"

namespace tp::geometry::internal {

/// One triangle's rest shape: its 2D corners relative to their centroid.
struct RestTriangle {
  std::array<int, 3> v{};          ///< 3D vertex indices
  std::array<Vec2, 3> rest_mm{};   ///< corners minus their centroid, pattern mm
  double dm_inv[2][2] = {};        ///< inverse of [r1 - r0, r2 - r0]
  double area_mm2 = 0;
  /// Gathered: the triangle lies on the longer side of an eased or gathered seam, whose excess
  /// the seam line takes up in pleats finer than the mesh. Compressions down to this stretch are
  /// kept (no pull back to rest); 0: the material's limit.
  double min_stretch = 0;
};

/// Two triangles sharing edge (a, b): c opposite in the first, d in the second.
struct BendStencil {
  int a = 0, b = 0, c = 0, d = 0;
  double rest_angle = 0;    ///< dihedral angle at rest (0: flat), radians
  double compliance = 0;    ///< 1 / stiffness (rad^2 per g mm^2 s^-2)
};

/// A seam segment held at its pattern length: the stitching and its allowance do not stretch
/// like the fabric beside them.
struct SeamEdge {
  int a = 0, b = 0;
  double rest_mm = 0;
};

/// The cloth: vertices, masses, constraints. Mass in g, length in mm, time in s.
struct ClothModel {
  std::vector<Vec3> x_mm;
  std::vector<double> inv_mass;               ///< #V 1/g
  std::vector<RestTriangle> triangles;
  std::vector<BendStencil> bends;
  std::vector<std::array<int, 2>> edges;      ///< unique undirected edges (self-collision)
  std::vector<int> vertex_piece;              ///< #V piece of the vertex's first chart
  std::vector<Vec2> vertex_rest_mm;           ///< #V the vertex in that chart (pattern mm)
  double mean_edge_mm = 0;
  /// Segments of plain seams (their sides' pattern lengths, or their seam's, agree within
  /// kPlainSeamSegment), projected to their rest length with the stitches. Draping: the sewn
  /// edges joining two charts; sewing: each side's segments between consecutive stitched vertices.
  std::vector<SeamEdge> seam_edges;
  /// Sewing only (empty when draping a sewn garment): vertex pairs a stitch draws together,
  /// and per vertex its weld group (the lowest vertex stitched to it, transitively; itself if
  /// none). Self-collision treats vertices of one group as one vertex, so seam sides can meet.
  std::vector<std::array<int, 2>> stitches;
  std::vector<int> weld_group;
  /// Sewing only: per stitched vertex, the sorted weld groups of itself and its mesh neighbours
  /// (empty for other vertices). Self-collision skips a pair where one primitive's vertex has
  /// the other's in this list: the seam's own neighbourhood closing is not a collision.
  std::vector<std::vector<int>> seam_near;
  /// Sewing only: per vertex, the stitch sides it lies near in its piece (2D distance to the
  /// side's nearest stitched vertex, that vertex's pair in `stitches`, code 2 x stitch + side).
  struct SeamZone {
    int pair = 0;
    int code = 0;
    double distance_mm = 0;
  };
  std::vector<std::vector<SeamZone>> seam_zones;
  /// Per vertex, the sorted codes of the zones it is in now: those whose pair is still further
  /// apart than the vertex is from the side. Two primitives in the zones of the two sides of one
  /// stitch do not collide: seam sides that start overlapping pass each other while they close
  /// (the dress's side seams overlap by up to 108 mm at the hem). The solver updates it before
  /// each pair search.
  std::vector<std::vector<int>> seam_zone_active;
};

/// Two sides of a seam segment whose pattern lengths differ by more than this share are eased
/// or gathered: no one rest length, left to the membrane.
inline constexpr double kPlainSeamSegment = 0.01;

/// Whether two sides' pattern lengths (of a segment, or summed over a seam) make a plain seam:
/// they differ by at most kPlainSeamSegment of the longer.
inline bool plain_seam_lengths(double a_mm, double b_mm) {
  return std::abs(a_mm - b_mm) <= kPlainSeamSegment * std::max(a_mm, b_mm);
}

/// A gathered triangle may compress a little beyond its seam's ratio: the gathers are not even
/// along a seam's segments.
inline constexpr double kGatherSlack = 0.9;

/// Marks the triangles of `piece_of_triangle[t] == piece` that have a vertex in `seam_vertices`
/// (sorted) as gathered down to `min_stretch` (the smallest mark wins).
void mark_gathered(std::vector<RestTriangle>& triangles, const std::vector<int>& seam_vertices, double min_stretch);

/// Builds the model of `g` (its 3D positions and its charts' rest shapes). Triangles a seam
/// collapsed are left out. Bending across an edge inside a piece rests flat; across a seam it
/// rests at the sewn angle (the seam allowance holds it). An edge joining two charts (a sewn
/// seam segment) whose lengths in them agree within kPlainSeamSegment, or that lies on a run of
/// such edges between the same two pieces whose summed lengths agree so (a plain seam, as XPBD
/// sewing judges a stitch), becomes a SeamEdge at their mean; otherwise (an eased or gathered
/// seam) the triangles of the longer side's piece at its ends are gathered
/// (RestTriangle::min_stretch, the two lengths' ratio). Stiffness from `m`.
ClothModel build_cloth_model(const Garment& g, const ClothMaterial& m);

/// Signed dihedral angle of stencil (a, b, c, d) at `x` (0 when flat) and, if grad is given,
/// its gradient with respect to a, b, c, d.
double dihedral_angle(const std::vector<Vec3>& x, const BendStencil& s, std::array<Vec3, 4>* grad);

}  // namespace tp::geometry::internal
