// geometry/preview/render_preview.h: front, side and back renders of a garment on its body.
#pragma once

#include <string>
#include <vector>

#include "geometry/body/body_mesh.h"
#include "geometry/common/image.h"
#include "geometry/garment/garment.h"

namespace tp::geometry {

/// Where the orthographic camera looks from.
enum class PreviewView { kFront, kSide, kBack };

/// Name of a view ("front", "side", "back").
std::string to_string(PreviewView view);

/// A piece's print as a texture: its image and the map from piece-local mm (the garment
/// piece's 2D mesh coordinates) to the image's pixel coordinates.
struct PieceTexture {
  ImageRgba8 image;
  Affine2 piece_mm_to_px;
};

/// Image size and content of a preview.
struct PreviewOptions {
  int width_px = 600;
  int height_px = 900;
  int supersample = 2;     ///< rendered at this many samples per pixel side, then averaged
  bool draw_body = true;   ///< draw the body (light grey) under the garment
  bool draw_seams = true;  ///< darken the piece outlines
  /// When set (one per garment piece, empty images allowed), pieces wear their texture through
  /// their 2D meshes (the UVs) instead of their piece colour.
  const std::vector<PieceTexture>* textures = nullptr;
};

/// A distinct colour for piece `index` (golden-angle hues), as in the paper's Figure 7.
Rgba8 piece_colour(int index);

/// Renders `garment` (pieces coloured by piece_colour) and optionally `body` with a z-buffered
/// software rasteriser and flat two-sided Lambert shading, orthographic, fitted to the image.
/// Front: seen from +z (the wearer's left on the image's right); side: from the wearer's left
/// (+x); back: from -z. Background is opaque white. `body` may be null.
ImageRgba8 render_preview(const Garment& garment, const BodyMesh* body, PreviewView view, const PreviewOptions& options = {});

}  // namespace tp::geometry
