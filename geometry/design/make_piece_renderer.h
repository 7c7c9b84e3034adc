// geometry/design/make_piece_renderer.h: builds the PieceRenderer of a garment job: the design
// sampled through the piece/garment correspondence, with textured seam allowance and marks.
#pragma once

#include <memory>

#include "geometry/allowance/finishing.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/design/design.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Accuracy and speed knobs of the renderer (defaults suit 600 dpi printing).
struct RenderOptions {
  /// Largest error, on the garment, of texture coordinates interpolated inside a render triangle
  /// (a quarter of a 600 dpi pixel).
  double tolerance_mm = 0.01;
  /// Render triangles are not split below this edge length (texture seams, allowance corners).
  double min_triangle_mm = 0.25;
  /// Trilinear taps along the major axis of a stretched pixel footprint.
  int max_anisotropy = 8;
  /// Finest cell of a planar layer's occlusion map (print: 0.5 mm; a preview can use its pixel).
  double occlusion_cell_mm = 0.5;
  /// Largest interpolation error of a layer's weight (0..1) inside a render triangle: half an
  /// 8-bit step for print. A planar layer's weight fades with the surface's angle, which is not
  /// affine in a triangle, so this splits the sides of the garment; a preview can use its own.
  double weight_tolerance = 1.0 / 512;
  /// The base keeps the last designs' planar occlusion maps and image pyramids for the next
  /// design made on it (the studio: one change after another). The pixels are the same either
  /// way; off, a base holds no design's data.
  bool keep_layer_data = false;
  /// Threads used while building (the render calls themselves are single-threaded and reentrant).
  int build_threads = 2;
};

/// The design-independent part of a garment job's renderer (surface, allowance sources, cut
/// outlines, band triangles, marks, the garment's closest-point index). Opaque; shared by every
/// renderer made from it, so it outlives them.
struct RendererBase;

/// Builds what every design on this garment and finishing shares, once (the studio keeps it per
/// garment session and only rebuilds the design's part after a change). Fails as make_piece_renderer
/// does for the garment, finishing and options.
[[nodiscard]] Result<std::shared_ptr<const RendererBase>> prepare_piece_renderer(const Pattern& pattern,
                                                                                 const Garment& garment,
                                                                                 const Finishing& finishing,
                                                                                 const RenderOptions& options = {},
                                                                                 const CancelToken* cancel = nullptr);

/// The renderer of `design` on a prepared base: the same renderer, pixel for pixel, as
/// make_piece_renderer with the base's pattern, garment, finishing and options.
[[nodiscard]] Result<std::unique_ptr<PieceRenderer>> make_piece_renderer(
    const std::shared_ptr<const RendererBase>& base, const Design& design, const CancelToken* cancel = nullptr);

/// The renderer of `design` on a prepared base keeping only what prints, for an overlay drawn over
/// another renderer (an order copy's text and labels): per piece the render triangles a layer or
/// mark prints on and those within `margin_mm` of them; the base itself is released unless a
/// stroke layer samples it. Renders as make_piece_renderer does wherever it prints, for pixels up
/// to margin_mm / 3; elsewhere it leaves the output as it is.
[[nodiscard]] Result<std::unique_ptr<PieceRenderer>> make_overlay_renderer(
    const std::shared_ptr<const RendererBase>& base, const Design& design, double margin_mm = 5,
    const CancelToken* cancel = nullptr);

/// Builds the renderer. Each piece pixel maps to (piece, triangle, barycentric) -> 3D point ->
/// the layers' colours, composited bottom first with their opacities; the seam allowance (widths
/// and corners from `finishing`) carries the partner piece's strip across sewn seams and the
/// mirror of the piece's own strip at hems and open edges; labels and grain arrows are printed in
/// the allowance when finishing.marks is kPrinted.
///
/// Fails (naming the piece, layer or field) when the garment does not match the pattern, the
/// design or finishing settings are invalid, a cut outline cannot be built, or `cancel` fires.
[[nodiscard]] Result<std::unique_ptr<PieceRenderer>> make_piece_renderer(const Pattern& pattern, const Garment& garment,
                                                                         const Design& design,
                                                                         const Finishing& finishing,
                                                                         const RenderOptions& options = {},
                                                                         const CancelToken* cancel = nullptr);

}  // namespace tp::geometry
