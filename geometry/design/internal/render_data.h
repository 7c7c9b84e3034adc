// geometry/design/internal/render_data.h: what the renderer precomputes per piece: small
// triangles in piece mm carrying every layer's texture coordinates as affine functions, a grid to
// find the triangles of a window, the cut outline and the printed marks.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/design/internal/depth_map.h"
#include "geometry/design/internal/stroke_field.h"
#include "geometry/design/internal/texture_fields.h"

namespace tp::geometry::internal {

/// f(x, y) = ax * x + ay * y + c over piece mm.
struct Linear2 {
  double ax = 0, ay = 0, c = 0;
  double at(Vec2 p) const { return ax * p.x + ay * p.y + c; }
};

/// Fits the affine function through three values at three points (zero for a degenerate triangle).
Linear2 fit_linear(const std::array<Vec2, 3>& p, const std::array<double, 3>& f);

/// One render triangle.
struct RenderTri {
  std::array<Vec2, 3> p;  ///< piece mm, counter-clockwise
  Linear2 x3, y3, z3;     ///< 3D surface point (for strokes and occlusion)
};

/// One layer that prints on one triangle (layers that leave a triangle blank have no entry).
struct TriLayer {
  enum Flags : std::uint8_t { kUnitWeight = 1, kDepthTest = 2 };
  Linear2 u, v, w;          ///< level-0 texel coordinates and weight (texture layers)
  std::uint16_t layer = 0;  ///< index into the design's layers
  std::uint8_t flags = 0;
  std::uint32_t first = 0;  ///< stroke layers: candidate segments in PieceData::stroke_segments
  std::uint32_t count = 0;
};

/// A straight mark stroke (label glyph or grain arrow), piece mm.
struct MarkSegment {
  Vec2 a, b;
  double half_width_mm = 0.15;
};

/// Everything render() needs for one piece.
struct PieceData {
  std::vector<RenderTri> tris;
  std::vector<std::uint32_t> layer_start;  ///< tris.size() + 1 offsets into `layers`
  std::vector<TriLayer> layers;            ///< per triangle, bottom layer first
  std::vector<std::uint32_t> stroke_segments;
  Polygon cut_outline;  ///< coverage outline (seam line + allowance)
  std::vector<MarkSegment> marks;
  std::uint32_t mark_colour = 0;  ///< premultiplied
  // Uniform grid over the triangles' bounds: cell -> triangle ids (CSR).
  Box2 grid_box;
  double cell_mm = 10;
  int nx = 0, ny = 0;
  std::vector<std::uint32_t> cell_start, cell_tris;
};

/// A design layer as the renderer sees it.
struct LayerRuntime {
  enum class Kind { kTexture, kStroke } kind = Kind::kTexture;
  double opacity = 1;
  std::unique_ptr<TextureField> texture;  ///< kTexture
  const PlanarField* planar = nullptr;    ///< kTexture from a planar projection (owned by `texture`)
  std::shared_ptr<const DepthMap> depth;  ///< planar occlusion (shared by renderers of one base)
  std::unique_ptr<StrokeField> stroke;    ///< kStroke
  std::uint32_t colour = 0;               ///< kStroke: premultiplied brush colour
};

}  // namespace tp::geometry::internal
