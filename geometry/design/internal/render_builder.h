// geometry/design/internal/render_builder.h: builds a piece's render triangles: its chart
// triangles and its allowance band, split until every layer's texture coordinates are affine
// inside each triangle to within the tolerance.
#pragma once

#include <array>
#include <vector>

#include "geometry/design/internal/allowance_source.h"
#include "geometry/design/internal/garment_surface.h"
#include "geometry/design/internal/render_data.h"

namespace tp::geometry::internal {

struct BuildContext {
  const GarmentSurface* surface = nullptr;
  const AllowanceSource* allowance = nullptr;
  const std::vector<LayerRuntime>* layers = nullptr;
  double tolerance_mm = 0.01;           ///< interpolation error budget on the garment surface
  double min_edge_mm = 0.25;            ///< triangles are not split below this size
  double weight_tolerance = 1.0 / 512;  ///< a layer weight's interpolation error budget (0..1)
  /// The allowance band (hidden in the sewn garment) copies its print with this many times the
  /// tolerance and never splits below `band_min_edge_mm`: its mapping bends at mitred corners,
  /// which would otherwise split the band into slivers for no visible gain.
  double band_tolerance_factor = 5;
  double band_min_edge_mm = 1.0;
  int max_depth = 7;        ///< nor more than this many times
  bool blank_band = false;  ///< the allowance band is left unprinted
};

/// Statistics of one build, for the log and the benchmark.
struct BuildStats {
  std::size_t source_triangles = 0;
  std::size_t band_triangles = 0;
  std::size_t render_triangles = 0;
  std::size_t splits = 0;
};

/// Fills out.tris / layer_start / layers / stroke_segments for `piece` from its chart triangles
/// [chart_first, chart_last) and the allowance band triangles `band` (piece mm). Each source
/// triangle is refined on its own, so runs built apart and joined in order equal one build.
BuildStats build_piece_triangles(int piece, int chart_first, int chart_last,
                                 const std::vector<std::array<Vec2, 3>>& band, const BuildContext& ctx, PieceData& out);

/// Builds the window-lookup grid over out.tris.
void build_grid(PieceData& out);

}  // namespace tp::geometry::internal
