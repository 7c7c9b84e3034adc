// geometry/garment/garment_obj.h: the 3D garment as Wavefront OBJ text (and its MTL) with texture coordinates.
#pragma once

#include <string>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Where each piece's printed image lies in one texture image (the atlas).
struct GarmentTexture {
  std::string mtl_file;      ///< e.g. "garment.mtl", named by `mtllib`
  std::string material;      ///< e.g. "print", named by `usemtl`
  std::string texture_file;  ///< e.g. "garment.png", the MTL's map_Kd
  int width_px = 0, height_px = 0;
  /// Per Pattern::pieces index: piece mm -> atlas pixel (x right, y down, row 0 on top).
  std::vector<Affine2> piece_mm_to_atlas_px;
};

/// OBJ text of `garment`. `v` are the shared 3D vertices in mm (body frame; the units are stated in
/// a comment: 1 OBJ unit = 1 mm, so a tool that takes units as metres needs a scale of 0.001); each
/// piece is a group `g <piece name>` whose faces `f v/vt` use its own `vt`. A seam vertex is one `v`
/// with one `vt` per joining piece.
///
/// With `texture`, the file names its MTL (`mtllib`, `usemtl`) and each `vt` is the vertex's place in
/// the atlas normalised to [0, 1] (u right, v up as OBJ has it). Without it (no print rendered, as
/// in `printctl garment`), `vt` are the piece's mesh coordinates in mm plus a per-piece offset that
/// lays the pieces side by side (`# piece <name> uv_offset_mm <dx> <dy>`).
std::string garment_to_obj(const Pattern& pattern, const Garment& garment, const GarmentTexture* texture = nullptr);

/// MTL text for `texture`: one material, lit white, its diffuse map the atlas image.
std::string garment_mtl(const GarmentTexture& texture);

}  // namespace tp::geometry
