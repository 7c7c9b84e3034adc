// geometry/design/make_piece_renderer.cpp: assembles layers, allowance bands and render
// triangles into the immutable renderer the RIP calls band by band.
#include "geometry/design/make_piece_renderer.h"

#include <algorithm>
#include <mutex>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/cut_outline.h"
#include "geometry/common/thread_pool.h"
#include "geometry/design/internal/allowance_source.h"
#include "geometry/design/internal/band_mesh.h"
#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"
#include "geometry/design/internal/piece_marks.h"
#include "geometry/design/internal/render_builder.h"
#include "geometry/design/raster/mip_image.h"
#include "geometry/design/raster/render_window.h"
#include "geometry/design/validate_design.h"

namespace tp::geometry {
namespace {

using namespace internal;

class DesignRenderer final : public PieceRenderer {
 public:
  int piece_count() const override { return static_cast<int>(pieces_.size()); }

  const Polygon& cut_outline_mm(int piece) const override { return cut_[static_cast<size_t>(piece)]; }

  void render(int piece, const Affine2& pixel_to_piece_mm, int width_px, int height_px, Rgba8* out,
              std::ptrdiff_t row_stride_px) const override {
    if (piece < 0 || piece >= piece_count()) return;
    render_window(pieces_[static_cast<size_t>(piece)], layers_, pixel_to_piece_mm, width_px, height_px, out,
                  row_stride_px, window_);
  }

  std::unique_ptr<GarmentSurface> surface_;
  std::unique_ptr<AllowanceSource> allowance_;
  std::unique_ptr<ClosestPointIndex> garment_index_;
  std::vector<LayerRuntime> layers_;
  std::vector<PieceData> pieces_;
  std::vector<Polygon> cut_;
  WindowOptions window_;
};

Result<std::vector<LayerRuntime>> make_layers(const Design& design, const GarmentSurface& surface,
                                              std::unique_ptr<ClosestPointIndex>& garment_index, double tolerance_mm) {
  std::vector<LayerRuntime> out;
  for (const DesignLayer& dl : design.layers) {
    LayerRuntime L;
    L.opacity = dl.opacity;
    if (const auto* c = std::get_if<CylindricalProjection>(&dl.content)) {
      L.texture = make_cylindrical_field(*c, surface, tolerance_mm);
    } else if (const auto* p = std::get_if<PlanarProjection>(&dl.content)) {
      auto field = std::make_unique<PlanarField>(*p, tolerance_mm);
      L.planar = field.get();
      L.depth = std::make_unique<DepthMap>(*field, surface, p->occlusion_tolerance_mm);
      L.texture = std::move(field);
    } else if (const auto* b = std::get_if<BrushStroke>(&dl.content)) {
      if (!garment_index)
        garment_index = std::make_unique<ClosestPointIndex>(surface.garment().vertices_mm, surface.triangles_3d());
      L.kind = LayerRuntime::Kind::kStroke;
      L.stroke = std::make_unique<StrokeField>(*b, surface, *garment_index);
      L.colour = premultiply(b->colour);
    } else if (const auto* t = std::get_if<TextureTransfer>(&dl.content)) {
      L.texture = make_transfer_field(*t, tolerance_mm);
    }
    out.push_back(std::move(L));
  }
  return out;
}

Polygon loop_polygon(const GarmentSurface& surface, int piece) {
  Polygon poly;
  const PieceChart& c = surface.chart(piece);
  for (int v : c.loop) poly.push_back(c.piece->mesh.vertices_mm[static_cast<size_t>(v)]);
  return poly;
}

}  // namespace

Result<std::unique_ptr<PieceRenderer>> make_piece_renderer(const Pattern& pattern, const Garment& garment,
                                                           const Design& design, const Finishing& finishing,
                                                           const RenderOptions& options, const CancelToken* cancel) {
  if (auto st = validate_design(design); !st) return std::unexpected(st.error());
  if (auto st = validate_finishing(pattern, finishing); !st) return std::unexpected(st.error());
  if (!(options.tolerance_mm > 0) || !(options.min_triangle_mm > 0))
    return fail(ErrorCode::kInvalidArgument, "render options: tolerance_mm and min_triangle_mm must be > 0");
  auto r = std::make_unique<DesignRenderer>();
  auto surface = GarmentSurface::build(pattern, garment);
  if (!surface) return std::unexpected(surface.error().with_context("garment"));
  r->surface_ = std::move(*surface);
  auto layers = make_layers(design, *r->surface_, r->garment_index_, options.tolerance_mm);
  if (!layers) return std::unexpected(layers.error());
  r->layers_ = std::move(*layers);
  r->allowance_ = std::make_unique<AllowanceSource>(*r->surface_);
  r->window_.max_anisotropy = std::max(1, options.max_anisotropy);

  const int n = r->surface_->piece_count();
  r->pieces_.resize(static_cast<size_t>(n));
  r->cut_.resize(static_cast<size_t>(n));
  BuildContext ctx;
  ctx.surface = r->surface_.get();
  ctx.allowance = r->allowance_.get();
  ctx.layers = &r->layers_;
  ctx.tolerance_mm = options.tolerance_mm;
  ctx.min_edge_mm = options.min_triangle_mm;
  ctx.blank_band = !finishing.textured_allowance;

  // Pieces are independent: build them on a few threads, keep the first error.
  std::mutex error_mutex;
  std::optional<Error> first_error;
  auto work = [&](int p) {
    if (cancel && cancel->cancelled()) {
      std::lock_guard lock(error_mutex);
      if (!first_error) first_error = Error{ErrorCode::kCancelled, "renderer build cancelled"};
      return;
    }
    const Piece& piece = pattern.pieces[static_cast<size_t>(p)];
    auto allowance = resolve_allowance(pattern, p, finishing);
    Result<Polygon> cut =
        allowance ? cut_outline(piece, *allowance, finishing.mitre_limit) : std::unexpected(allowance.error());
    const Polygon mesh_loop = loop_polygon(*r->surface_, p);
    std::vector<std::vector<Vec2>> edges;
    for (const Edge& e : piece.edges) edges.push_back(e.points_mm);
    // The band reaches the cut line everywhere and at least the mesh boundary (whose chords
    // may bulge past a curved seam line where an edge has no allowance).
    Result<Polygon> outer =
        cut ? cut_outline(edges, allowance->width_mm, allowance->corner, finishing.mitre_limit, &mesh_loop)
            : std::unexpected(cut.error());
    if (!outer) {
      std::lock_guard lock(error_mutex);
      if (!first_error) first_error = outer.error().with_context("piece '" + piece.name + "'");
      return;
    }
    PieceData& pd = r->pieces_[static_cast<size_t>(p)];
    r->cut_[static_cast<size_t>(p)] = *cut;
    pd.cut_outline = *cut;
    // Band triangles about as long as the seam segments they face.
    double seg = 0;
    for (size_t i = 0; i < mesh_loop.size(); ++i) seg += norm(mesh_loop[(i + 1) % mesh_loop.size()] - mesh_loop[i]);
    const double spacing = std::clamp(seg / std::max<size_t>(1, mesh_loop.size()), 2.0, 20.0);
    // Break lines long enough to cross the widest allowance along a sharp corner's mitre.
    const double widest = *std::max_element(allowance->width_mm.begin(), allowance->width_mm.end());
    const auto band = triangulate_band(mesh_loop, *outer, spacing, r->allowance_->source_breaks(p, 4 * widest + 5));
    build_piece_triangles(p, band, ctx, pd);
    if (finishing.marks == MarkMode::kPrinted) {
      pd.marks = printed_marks(pattern, p, *allowance, finishing);
      pd.mark_colour = premultiply(finishing.mark_colour);
    }
    build_grid(pd);
  };
  ThreadPool pool(std::clamp(options.build_threads, 1, std::max(1, n)));
  pool.parallel_for(n, [&](int p, int) { work(p); });
  if (first_error) return std::unexpected(*first_error);
  return std::unique_ptr<PieceRenderer>(std::move(r));
}

}  // namespace tp::geometry
