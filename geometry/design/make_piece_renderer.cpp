// geometry/design/make_piece_renderer.cpp: assembles layers, allowance bands and render
// triangles into the immutable renderer the RIP calls band by band.
#include "geometry/design/make_piece_renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <list>
#include <mutex>
#include <optional>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/cut_outline.h"
#include "geometry/common/thread_pool.h"
#include "geometry/design/internal/allowance_source.h"
#include "geometry/design/internal/band_mesh.h"
#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"
#include "geometry/design/internal/keep_printing_triangles.h"
#include "geometry/design/internal/piece_marks.h"
#include "geometry/design/internal/render_builder.h"
#include "geometry/design/raster/mip_cache.h"
#include "geometry/design/raster/mip_image.h"
#include "geometry/design/raster/render_window.h"
#include "geometry/design/validate_design.h"

namespace tp::geometry {

using namespace internal;

/// What every design on one garment shares: the surface, the allowance sources, each piece's cut
/// outline, allowance band triangles and printed marks, and (once a stroke asks) the garment's
/// closest-point index. Read-only once built, except the index made on first use and the few
/// planar occlusion maps it keeps for the next design.
struct RendererBase {
  struct Piece {
    Polygon cut;
    std::vector<std::array<Vec2, 3>> band;
    std::vector<MarkSegment> marks;
  };
  RenderOptions options;
  bool blank_band = false;
  bool printed_marks = false;
  std::uint32_t mark_colour = 0;
  std::unique_ptr<GarmentSurface> surface;
  std::unique_ptr<AllowanceSource> allowance;
  std::vector<Piece> pieces;
  /// The image pyramids of the last designs' layers (the same image object, still alive).
  mutable MipCache mips;
  MipCache* kept_mips() const { return options.keep_layer_data ? &mips : nullptr; }

  const ClosestPointIndex& garment_index() const {
    std::call_once(index_once_, [this] {
      index_ = std::make_unique<ClosestPointIndex>(surface->garment().vertices_mm, surface->triangles_3d());
    });
    return *index_;
  }

  /// The occlusion map of a planar layer: it depends only on where the image plane is (centre,
  /// normal, up), the occlusion tolerance and the cell, not on the image or its size, so a
  /// design that changes anything else reuses the last ones made on this base.
  std::shared_ptr<const DepthMap> depth_map(const PlanarProjection& p, const PlanarField& field) const {
    if (!options.keep_layer_data)
      return std::make_shared<const DepthMap>(field, *surface, p.occlusion_tolerance_mm, options.occlusion_cell_mm);
    const std::array<double, 11> key{p.centre_mm.x,
                                     p.centre_mm.y,
                                     p.centre_mm.z,
                                     p.normal.x,
                                     p.normal.y,
                                     p.normal.z,
                                     p.up.x,
                                     p.up.y,
                                     p.up.z,
                                     p.occlusion_tolerance_mm,
                                     options.occlusion_cell_mm};
    {
      std::lock_guard lock(depth_mu_);
      for (auto it = depth_maps_.begin(); it != depth_maps_.end(); ++it)
        if (it->first == key) {
          depth_maps_.splice(depth_maps_.begin(), depth_maps_, it);
          return depth_maps_.front().second;
        }
    }
    auto map = std::make_shared<const DepthMap>(field, *surface, p.occlusion_tolerance_mm, options.occlusion_cell_mm);
    std::lock_guard lock(depth_mu_);
    depth_maps_.emplace_front(key, map);
    if (depth_maps_.size() > kKeptDepthMaps) depth_maps_.pop_back();
    return map;
  }

 private:
  static constexpr std::size_t kKeptDepthMaps = 2;
  mutable std::once_flag index_once_;
  mutable std::unique_ptr<ClosestPointIndex> index_;
  mutable std::mutex depth_mu_;
  mutable std::list<std::pair<std::array<double, 11>, std::shared_ptr<const DepthMap>>> depth_maps_;
};

namespace {

class DesignRenderer final : public PieceRenderer {
 public:
  int piece_count() const override { return static_cast<int>(pieces_.size()); }

  const Polygon& cut_outline_mm(int piece) const override { return pieces_[static_cast<size_t>(piece)].cut_outline; }

  void render(int piece, const Affine2& pixel_to_piece_mm, int width_px, int height_px, Rgba8* out,
              std::ptrdiff_t row_stride_px) const override {
    if (piece < 0 || piece >= piece_count()) return;
    render_window(pieces_[static_cast<size_t>(piece)], layers_, pixel_to_piece_mm, width_px, height_px, out,
                  row_stride_px, window_);
  }

  std::shared_ptr<const RendererBase> base_;
  std::vector<LayerRuntime> layers_;
  std::vector<PieceData> pieces_;
  WindowOptions window_;
};

std::vector<LayerRuntime> make_layers(const Design& design, const RendererBase& base) {
  const GarmentSurface& surface = *base.surface;
  const double tolerance_mm = base.options.tolerance_mm;
  std::vector<LayerRuntime> out;
  for (const DesignLayer& dl : design.layers) {
    LayerRuntime L;
    L.opacity = dl.opacity;
    if (const auto* c = std::get_if<CylindricalProjection>(&dl.content)) {
      L.texture = make_cylindrical_field(*c, surface, tolerance_mm, base.kept_mips());
    } else if (const auto* p = std::get_if<PlanarProjection>(&dl.content)) {
      auto field = std::make_unique<PlanarField>(*p, tolerance_mm, base.kept_mips());
      L.planar = field.get();
      L.depth = base.depth_map(*p, *field);
      L.texture = std::move(field);
    } else if (const auto* b = std::get_if<BrushStroke>(&dl.content)) {
      L.kind = LayerRuntime::Kind::kStroke;
      L.stroke = std::make_unique<StrokeField>(*b, surface, base.garment_index());
      L.colour = premultiply(b->colour);
    } else if (const auto* t = std::get_if<TextureTransfer>(&dl.content)) {
      L.texture = make_transfer_field(*t, tolerance_mm, base.kept_mips());
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

// Appends `part` (triangles built from a later run of the same piece's sources) to `dst`.
void append_part(PieceData& dst, const PieceData& part) {
  const auto layer_offset = static_cast<std::uint32_t>(dst.layers.size());
  const auto segment_offset = static_cast<std::uint32_t>(dst.stroke_segments.size());
  dst.tris.insert(dst.tris.end(), part.tris.begin(), part.tris.end());
  for (size_t i = 1; i < part.layer_start.size(); ++i) dst.layer_start.push_back(part.layer_start[i] + layer_offset);
  for (TriLayer e : part.layers) {
    if (e.count > 0) e.first += segment_offset;  // stroke entries; texture ones keep first = 0
    dst.layers.push_back(e);
  }
  dst.stroke_segments.insert(dst.stroke_segments.end(), part.stroke_segments.begin(), part.stroke_segments.end());
}

// Source triangles per build task: small enough that a piece's work spreads over the threads.
constexpr int kTrianglesPerTask = 48;

}  // namespace

Result<std::shared_ptr<const RendererBase>> prepare_piece_renderer(const Pattern& pattern, const Garment& garment,
                                                                   const Finishing& finishing,
                                                                   const RenderOptions& options,
                                                                   const CancelToken* cancel) {
  if (auto st = validate_finishing(pattern, finishing); !st) return std::unexpected(st.error());
  if (!(options.tolerance_mm > 0) || !(options.min_triangle_mm > 0) || !(options.occlusion_cell_mm > 0) ||
      !(options.weight_tolerance > 0))
    return fail(ErrorCode::kInvalidArgument,
                "render options: tolerance_mm, min_triangle_mm, occlusion_cell_mm and weight_tolerance must be > 0");
  auto base = std::make_shared<RendererBase>();
  base->options = options;
  base->blank_band = !finishing.textured_allowance;
  base->printed_marks = finishing.marks == MarkMode::kPrinted;
  base->mark_colour = premultiply(finishing.mark_colour);
  auto surface = GarmentSurface::build(pattern, garment);
  if (!surface) return std::unexpected(surface.error().with_context("garment"));
  base->surface = std::move(*surface);
  base->allowance = std::make_unique<AllowanceSource>(*base->surface);

  const int n = base->surface->piece_count();
  base->pieces.resize(static_cast<size_t>(n));
  std::vector<std::optional<Error>> errors(static_cast<size_t>(n));
  auto work = [&](int p) {
    std::optional<Error>& error = errors[static_cast<size_t>(p)];
    if (cancel && cancel->cancelled()) {
      error = Error{ErrorCode::kCancelled, "renderer build cancelled"};
      return;
    }
    const Piece& piece = pattern.pieces[static_cast<size_t>(p)];
    auto allowance = resolve_allowance(pattern, p, finishing);
    Result<Polygon> cut =
        allowance ? cut_outline(piece, *allowance, finishing.mitre_limit) : std::unexpected(allowance.error());
    const Polygon mesh_loop = loop_polygon(*base->surface, p);
    std::vector<std::vector<Vec2>> edges;
    for (const Edge& e : piece.edges) edges.push_back(e.points_mm);
    // The band reaches the cut line everywhere and at least the mesh boundary (whose chords
    // may bulge past a curved seam line where an edge has no allowance).
    Result<Polygon> outer =
        cut ? cut_outline(edges, allowance->width_mm, allowance->corner, finishing.mitre_limit, &mesh_loop)
            : std::unexpected(cut.error());
    if (!outer) {
      error = outer.error().with_context("piece '" + piece.name + "'");
      return;
    }
    RendererBase::Piece& bp = base->pieces[static_cast<size_t>(p)];
    bp.cut = *cut;
    // Band triangles about as long as the seam segments they face.
    double seg = 0;
    for (size_t i = 0; i < mesh_loop.size(); ++i) seg += norm(mesh_loop[(i + 1) % mesh_loop.size()] - mesh_loop[i]);
    const double spacing = std::clamp(seg / std::max<size_t>(1, mesh_loop.size()), 2.0, 20.0);
    // Break lines long enough to cross the widest allowance along a sharp corner's mitre.
    const double widest = *std::max_element(allowance->width_mm.begin(), allowance->width_mm.end());
    bp.band = triangulate_band(mesh_loop, *outer, spacing, base->allowance->source_breaks(p, 4 * widest + 5));
    if (base->printed_marks) bp.marks = printed_marks(pattern, p, *allowance, finishing);
  };
  ThreadPool pool(std::clamp(options.build_threads, 1, std::max(1, n)));
  pool.parallel_for(n, [&](int p, int) { work(p); });
  for (const auto& e : errors)
    if (e) return std::unexpected(*e);
  return std::shared_ptr<const RendererBase>(std::move(base));
}

Result<std::unique_ptr<PieceRenderer>> make_piece_renderer(const std::shared_ptr<const RendererBase>& base,
                                                           const Design& design, const CancelToken* cancel) {
  if (!base) return fail(ErrorCode::kInvalidArgument, "renderer base: none given");
  if (auto st = validate_design(design); !st) return std::unexpected(st.error());
  auto r = std::make_unique<DesignRenderer>();
  r->base_ = base;
  r->layers_ = make_layers(design, *base);
  r->window_.max_anisotropy = std::max(1, base->options.max_anisotropy);

  const GarmentSurface& surface = *base->surface;
  const int n = surface.piece_count();
  BuildContext ctx;
  ctx.surface = &surface;
  ctx.allowance = base->allowance.get();
  ctx.layers = &r->layers_;
  ctx.tolerance_mm = base->options.tolerance_mm;
  ctx.min_edge_mm = base->options.min_triangle_mm;
  ctx.weight_tolerance = base->options.weight_tolerance;
  ctx.blank_band = base->blank_band;

  // Each piece's chart and band triangles in runs, the runs spread over the threads and joined
  // in order: every source triangle is refined on its own, so the result does not depend on how
  // the work was split.
  struct Task {
    int piece, chart_first, chart_last, band_first, band_last;
  };
  std::vector<Task> tasks;
  std::vector<size_t> first_task(static_cast<size_t>(n) + 1, 0);
  for (int p = 0; p < n; ++p) {
    first_task[static_cast<size_t>(p)] = tasks.size();
    const int chart = static_cast<int>(surface.chart(p).piece->mesh.triangles.size());
    const int band = static_cast<int>(base->pieces[static_cast<size_t>(p)].band.size());
    for (int t = 0; t < chart; t += kTrianglesPerTask)
      tasks.push_back({p, t, std::min(chart, t + kTrianglesPerTask), 0, 0});
    for (int t = 0; t < band; t += kTrianglesPerTask)
      tasks.push_back({p, 0, 0, t, std::min(band, t + kTrianglesPerTask)});
  }
  first_task[static_cast<size_t>(n)] = tasks.size();
  std::vector<PieceData> parts(tasks.size());
  std::atomic<bool> cancelled{false};
  ThreadPool pool(std::max(1, base->options.build_threads));
  pool.parallel_for(static_cast<int>(tasks.size()), [&](int i, int) {
    if (cancel && cancel->cancelled()) {
      cancelled = true;
      return;
    }
    const Task& t = tasks[static_cast<size_t>(i)];
    const auto& band = base->pieces[static_cast<size_t>(t.piece)].band;
    const std::vector<std::array<Vec2, 3>> band_run(band.begin() + t.band_first, band.begin() + t.band_last);
    build_piece_triangles(t.piece, t.chart_first, t.chart_last, band_run, ctx, parts[static_cast<size_t>(i)]);
  });
  if (cancelled) return fail(ErrorCode::kCancelled, "renderer build cancelled");

  r->pieces_.resize(static_cast<size_t>(n));
  pool.parallel_for(n, [&](int p, int) {
    PieceData& pd = r->pieces_[static_cast<size_t>(p)];
    pd.layer_start.assign(1, 0);
    for (size_t i = first_task[static_cast<size_t>(p)]; i < first_task[static_cast<size_t>(p) + 1]; ++i)
      append_part(pd, parts[i]);
    const RendererBase::Piece& bp = base->pieces[static_cast<size_t>(p)];
    pd.cut_outline = bp.cut;
    if (base->printed_marks) {
      pd.marks = bp.marks;
      pd.mark_colour = base->mark_colour;
    }
    build_grid(pd);
  });
  return std::unique_ptr<PieceRenderer>(std::move(r));
}

Result<std::unique_ptr<PieceRenderer>> make_overlay_renderer(const std::shared_ptr<const RendererBase>& base,
                                                             const Design& design, double margin_mm,
                                                             const CancelToken* cancel) {
  if (!(margin_mm > 0)) return fail(ErrorCode::kInvalidArgument, "overlay renderer: margin_mm must be > 0");
  auto r = make_piece_renderer(base, design, cancel);
  if (!r) return r;
  auto& dr = static_cast<DesignRenderer&>(**r);
  for (PieceData& pd : dr.pieces_) keep_printing_triangles(pd, dr.layers_, margin_mm);
  const bool strokes = std::any_of(dr.layers_.begin(), dr.layers_.end(),
                                   [](const LayerRuntime& L) { return L.kind == LayerRuntime::Kind::kStroke; });
  if (!strokes) dr.base_.reset();
  return r;
}

Result<std::unique_ptr<PieceRenderer>> make_piece_renderer(const Pattern& pattern, const Garment& garment,
                                                           const Design& design, const Finishing& finishing,
                                                           const RenderOptions& options, const CancelToken* cancel) {
  if (auto st = validate_design(design); !st) return std::unexpected(st.error());
  auto base = prepare_piece_renderer(pattern, garment, finishing, options, cancel);
  if (!base) return std::unexpected(base.error());
  return make_piece_renderer(*base, design, cancel);
}

}  // namespace tp::geometry
