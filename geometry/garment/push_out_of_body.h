// geometry/garment/push_out_of_body.h: placed pieces moved out of the body by a smooth push before sewing.
#pragma once

#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/mesh/mesh_pattern.h"

namespace tp::geometry {

/// What push_out_of_body found and did (vertex counts over all pieces).
struct PushOutStats {
  int vertices = 0;        ///< vertices of all pieces
  int inside_before = 0;   ///< vertices inside the body as placed
  int close_before = 0;    ///< vertices inside or nearer than the clearance as placed
  int inside_after = 0;    ///< vertices still inside after the push
  int close_after = 0;     ///< vertices still inside or nearer than the clearance after the push
  int passes = 0;          ///< smoothing passes run
  double max_push_mm = 0;  ///< largest displacement of one vertex
};

/// Moves every piece's start positions out of `body` to at least `clearance_mm` outside it.
///
/// Each vertex inside or nearer than the clearance wants a push along the body's outward normal
/// (the signed distance's gradient) to the clearance; deeper than the SDF's exact band, along the
/// shortest of 26 rays out of the body, to the clearance beyond. Where a piece's pushes agree in
/// direction (a panel cutting into the torso), the first two passes move the piece whole
/// (rigidly, along their mean). Otherwise (a sleeve round an arm too thick for it) the pushes are
/// spread over the piece as one smooth field: each vertex moves by the weighted mean of the pushes
/// within a radius of it (distances in the flat piece, so the two sides of a tube do not mix),
/// stretched to the largest weighted push where they agree, so a piece moves as a sheet and never
/// as single vertices pulled into spikes. Repeated (at most 12 passes; from the third the radius
/// halves each pass, from `radius_mm` down to 15 mm, so pushes all round a tube stop cancelling)
/// until no vertex is nearer than the clearance. Pieces clear of the body are not touched.
/// Deterministic.
/// @param[in,out] start_mm  per piece, the 3D start of each vertex of `meshes.pieces[i]` (mm)
/// @param[in] meshes        the pieces' flat meshes (their vertices give the field's distances)
void push_out_of_body(std::vector<std::vector<Vec3>>& start_mm, const PatternMesh& meshes, const BodySdf& body,
                      double clearance_mm, double radius_mm, PushOutStats* stats = nullptr);

}  // namespace tp::geometry
