// geometry/design/internal/render_builder.cpp: adaptive splitting of render triangles and the
// per-triangle, per-layer data the render loop reads.
//
// Error bound: inside a triangle the renderer interpolates texture coordinates linearly. A
// triangle is split 1-to-4 until, at its three edge midpoints, the exact coordinates differ from
// the interpolated ones by at most tolerance_mm on the garment (converted to texels per layer).
// Planar coordinates are affine in the 3D point and never split a chart triangle; a cylinder's
// angle is nearly affine (error about a^3/8 * r for a triangle spanning angle a at radius r,
// under 0.01 mm for a 20 mm triangle at 150 mm); texture transfer splits at its UV seams.
#include "geometry/design/internal/render_builder.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry::internal {
namespace {

// Weights this close to 0 or 1 are treated as exactly 0 or 1.
constexpr double kWeightSnap = 1e-4;

struct Vtx {
  Vec2 pos;
  int piece = -1;
  ChartLocation loc;
  SurfacePoint sp;
  std::vector<FieldSample> f;  // per layer (texture layers only)
};

double unwrap_near(double value, double ref, double period) {
  if (period <= 0) return value;
  return value + period * std::round((ref - value) / period);
}

class Builder {
 public:
  Builder(int piece, const BuildContext& ctx, PieceData& out, BuildStats& stats)
      : piece_(piece), ctx_(ctx), out_(out), stats_(stats), layers_(*ctx.layers) {}

  void add_chart_triangle(int t) {
    const GarmentPiece& gp = *ctx_.surface->chart(piece_).piece;
    const auto& tri = gp.mesh.triangles[static_cast<size_t>(t)];
    std::array<Vtx, 3> v;
    for (int k = 0; k < 3; ++k) {
      Vtx& x = v[static_cast<size_t>(k)];
      x.pos = gp.mesh.vertices_mm[static_cast<size_t>(tri[static_cast<size_t>(k)])];
      x.piece = piece_;
      x.loc.triangle = t;
      x.loc.bary = {0, 0, 0};
      x.loc.bary[static_cast<size_t>(k)] = 1;
      fill(x);
    }
    if (cross(v[1].pos - v[0].pos, v[2].pos - v[0].pos) <= 0) return;
    refine(v, 0);
  }

  void add_band_triangle(const std::array<Vec2, 3>& t) {
    if (ctx_.blank_band) {
      // Claims its pixels so nothing bleeds in, with no layer printing on it.
      RenderTri rt;
      rt.p = t;
      out_.tris.push_back(rt);
      out_.layer_start.push_back(static_cast<std::uint32_t>(out_.layers.size()));
      return;
    }
    refine_band(t, 0);
  }

 private:
  void fill(Vtx& x) const {
    x.sp = ctx_.surface->at(x.piece, x.loc);
    x.f.assign(layers_.size(), FieldSample{});
    for (size_t l = 0; l < layers_.size(); ++l)
      if (layers_[l].texture) x.f[l] = layers_[l].texture->eval(x.sp);
  }

  // A band point mapped through boundary segment `segment`'s quad: every point of one render
  // triangle uses the same quad, so a triangle touching a mitre line where the print source
  // changes never blends the two sources.
  Vtx band_vertex(Vec2 p, int segment) const {
    Vtx x;
    x.pos = p;
    const AllowanceSample s = ctx_.allowance->source(piece_, ctx_.allowance->seam_coordinates_in(piece_, segment, p));
    x.piece = s.piece;
    x.loc = s.location;
    if (x.piece < 0 || x.loc.triangle < 0) {
      // No source (degenerate boundary): use the nearest point of the piece itself.
      x.piece = piece_;
      x.loc = ctx_.surface->chart(piece_).locator.nearest(p);
    }
    fill(x);
    return x;
  }

  Vtx midpoint(const Vtx& a, const Vtx& b, int band_segment) const {
    if (band_segment >= 0) return band_vertex((a.pos + b.pos) * 0.5, band_segment);
    // Inside one chart triangle everything but the layers' own maps is affine.
    Vtx m;
    m.pos = (a.pos + b.pos) * 0.5;
    m.piece = a.piece;
    m.loc.triangle = a.loc.triangle;
    for (int k = 0; k < 3; ++k)
      m.loc.bary[static_cast<size_t>(k)] =
          0.5 * (a.loc.bary[static_cast<size_t>(k)] + b.loc.bary[static_cast<size_t>(k)]);
    fill(m);
    return m;
  }

  // Interpolation error at the midpoint of (a, b), in units of the tolerance (> 1: split).
  double error(const Vtx& a, const Vtx& b, const Vtx& m, bool band) const {
    double e = 0;
    for (size_t l = 0; l < layers_.size(); ++l) {
      const TextureField* tf = layers_[l].texture.get();
      if (!tf) continue;
      const double P = tf->period_u();
      const double ub = unwrap_near(b.f[l].u, a.f[l].u, P);
      const double um = unwrap_near(m.f[l].u, a.f[l].u, P);
      const double du = std::abs(um - 0.5 * (a.f[l].u + ub));
      const double dv = std::abs(m.f[l].v - 0.5 * (a.f[l].v + b.f[l].v));
      const double dw = std::abs(m.f[l].w - 0.5 * (a.f[l].w + b.f[l].w));
      // Where the layer leaves all three points blank, its coordinates do not matter.
      if (a.f[l].w <= kWeightSnap && b.f[l].w <= kWeightSnap && m.f[l].w <= kWeightSnap) continue;
      const double tol = tf->tolerance_texels * (band ? ctx_.band_tolerance_factor : 1.0);
      e = std::max({e, du / tol, dv / tol, dw / ctx_.weight_tolerance});
    }
    if (band) {
      // Strokes and occlusion read the interpolated 3D point.
      const Vec3 d = m.sp.position_mm - (a.sp.position_mm + b.sp.position_mm) * 0.5;
      e = std::max(e, norm(d) / (ctx_.band_tolerance_factor * ctx_.tolerance_mm));
    }
    return e;
  }

  void refine(const std::array<Vtx, 3>& v, int depth) {
    const double longest = std::max({norm(v[1].pos - v[0].pos), norm(v[2].pos - v[1].pos), norm(v[0].pos - v[2].pos)});
    if (depth < ctx_.max_depth && longest > ctx_.min_edge_mm) {
      const Vtx m01 = midpoint(v[0], v[1], -1), m12 = midpoint(v[1], v[2], -1), m20 = midpoint(v[2], v[0], -1);
      const double e =
          std::max({error(v[0], v[1], m01, false), error(v[1], v[2], m12, false), error(v[2], v[0], m20, false)});
      if (e > 1) {
        ++stats_.splits;
        refine({v[0], m01, m20}, depth + 1);
        refine({m01, v[1], m12}, depth + 1);
        refine({m20, m12, v[2]}, depth + 1);
        refine({m01, m12, m20}, depth + 1);
        return;
      }
    }
    emit(v);
  }

  // Band triangles pick their boundary segment from their centroid, then split like chart ones.
  void refine_band(const std::array<Vec2, 3>& p, int depth) {
    const int seg = ctx_.allowance->seam_coordinates(piece_, (p[0] + p[1] + p[2]) / 3.0).segment;
    const std::array<Vtx, 3> v{band_vertex(p[0], seg), band_vertex(p[1], seg), band_vertex(p[2], seg)};
    const double longest = std::max({norm(p[1] - p[0]), norm(p[2] - p[1]), norm(p[0] - p[2])});
    if (depth < ctx_.max_depth && longest > ctx_.band_min_edge_mm) {
      const Vtx m01 = midpoint(v[0], v[1], seg), m12 = midpoint(v[1], v[2], seg), m20 = midpoint(v[2], v[0], seg);
      const double e =
          std::max({error(v[0], v[1], m01, true), error(v[1], v[2], m12, true), error(v[2], v[0], m20, true)});
      if (e > 1) {
        ++stats_.splits;
        const Vec2 a = m01.pos, b = m12.pos, c = m20.pos;
        refine_band({p[0], a, c}, depth + 1);
        refine_band({a, p[1], b}, depth + 1);
        refine_band({c, b, p[2]}, depth + 1);
        refine_band({a, b, c}, depth + 1);
        return;
      }
    }
    emit(v);
  }

  void emit(const std::array<Vtx, 3>& v) {
    RenderTri rt;
    rt.p = {v[0].pos, v[1].pos, v[2].pos};
    if (cross(rt.p[1] - rt.p[0], rt.p[2] - rt.p[0]) <= 0) return;
    rt.x3 = fit_linear(rt.p, {v[0].sp.position_mm.x, v[1].sp.position_mm.x, v[2].sp.position_mm.x});
    rt.y3 = fit_linear(rt.p, {v[0].sp.position_mm.y, v[1].sp.position_mm.y, v[2].sp.position_mm.y});
    rt.z3 = fit_linear(rt.p, {v[0].sp.position_mm.z, v[1].sp.position_mm.z, v[2].sp.position_mm.z});
    out_.tris.push_back(rt);
    for (size_t l = 0; l < layers_.size(); ++l) {
      const LayerRuntime& L = layers_[l];
      TriLayer e;
      e.layer = static_cast<std::uint16_t>(l);
      if (L.kind == LayerRuntime::Kind::kStroke) {
        scratch_.clear();
        L.stroke->candidates({v[0].piece, v[1].piece, v[2].piece}, {v[0].loc, v[1].loc, v[2].loc},
                             {v[0].sp.position_mm, v[1].sp.position_mm, v[2].sp.position_mm}, scratch_);
        if (scratch_.empty()) continue;
        e.first = static_cast<std::uint32_t>(out_.stroke_segments.size());
        e.count = static_cast<std::uint32_t>(scratch_.size());
        for (int s : scratch_) out_.stroke_segments.push_back(static_cast<std::uint32_t>(s));
        out_.layers.push_back(e);
        continue;
      }
      const double w0 = v[0].f[l].w, w1 = v[1].f[l].w, w2 = v[2].f[l].w;
      if (std::max({w0, w1, w2}) <= kWeightSnap) continue;
      const double P = L.texture->period_u();
      const double u0 = v[0].f[l].u;
      e.u = fit_linear(rt.p, {u0, unwrap_near(v[1].f[l].u, u0, P), unwrap_near(v[2].f[l].u, u0, P)});
      e.v = fit_linear(rt.p, {v[0].f[l].v, v[1].f[l].v, v[2].f[l].v});
      e.w = fit_linear(rt.p, {w0, w1, w2});
      if (std::min({w0, w1, w2}) >= 1 - kWeightSnap) e.flags |= TriLayer::kUnitWeight;
      if (L.depth) {
        std::array<Vec3, 3> pc;
        for (int k = 0; k < 3; ++k)
          pc[static_cast<size_t>(k)] = L.planar->plane_coordinates(v[static_cast<size_t>(k)].sp.position_mm);
        const auto cov = L.depth->classify(pc);
        if (cov == DepthMap::Coverage::kHidden) continue;
        if (cov == DepthMap::Coverage::kPartial) e.flags |= TriLayer::kDepthTest;
      }
      out_.layers.push_back(e);
    }
    out_.layer_start.push_back(static_cast<std::uint32_t>(out_.layers.size()));
  }

  int piece_;
  const BuildContext& ctx_;
  PieceData& out_;
  BuildStats& stats_;
  const std::vector<LayerRuntime>& layers_;
  std::vector<int> scratch_;
};

}  // namespace

Linear2 fit_linear(const std::array<Vec2, 3>& p, const std::array<double, 3>& f) {
  const Vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const double det = cross(e1, e2);
  if (det == 0) return {0, 0, f[0]};
  const double d1 = f[1] - f[0], d2 = f[2] - f[0];
  Linear2 l;
  l.ax = (d1 * e2.y - d2 * e1.y) / det;
  l.ay = (d2 * e1.x - d1 * e2.x) / det;
  l.c = f[0] - l.ax * p[0].x - l.ay * p[0].y;
  return l;
}

BuildStats build_piece_triangles(int piece, int chart_first, int chart_last,
                                 const std::vector<std::array<Vec2, 3>>& band, const BuildContext& ctx,
                                 PieceData& out) {
  BuildStats stats;
  out.tris.clear();
  out.layers.clear();
  out.stroke_segments.clear();
  out.layer_start.assign(1, 0);
  Builder b(piece, ctx, out, stats);
  const GarmentPiece& gp = *ctx.surface->chart(piece).piece;
  stats.band_triangles = band.size();
  const int chart = static_cast<int>(gp.mesh.triangles.size());
  for (int t = std::max(0, chart_first); t < std::min(chart, chart_last); ++t) b.add_chart_triangle(t);
  for (const auto& t : band) b.add_band_triangle(t);
  stats.source_triangles = static_cast<size_t>(std::max(0, std::min(chart, chart_last) - std::max(0, chart_first)));
  stats.render_triangles = out.tris.size();
  return stats;
}

void build_grid(PieceData& out) {
  out.grid_box = Box2{};
  for (const RenderTri& t : out.tris)
    for (Vec2 p : t.p) out.grid_box.add(p);
  for (Vec2 p : out.cut_outline) out.grid_box.add(p);
  if (out.grid_box.empty()) {
    out.nx = out.ny = 0;
    return;
  }
  // Cells of about four triangles keep window queries short.
  const double area = std::max(out.grid_box.width() * out.grid_box.height(), 1e-6);
  out.cell_mm = std::max(std::sqrt(area / std::max<size_t>(1, out.tris.size()) * 4.0), 0.5);
  out.nx = std::max(1, static_cast<int>(std::ceil(out.grid_box.width() / out.cell_mm)) + 1);
  out.ny = std::max(1, static_cast<int>(std::ceil(out.grid_box.height() / out.cell_mm)) + 1);
  auto cell_range = [&](const RenderTri& t, int& x0, int& x1, int& y0, int& y1) {
    Box2 b;
    for (Vec2 p : t.p) b.add(p);
    x0 = std::clamp(static_cast<int>(std::floor((b.min.x - out.grid_box.min.x) / out.cell_mm)), 0, out.nx - 1);
    x1 = std::clamp(static_cast<int>(std::floor((b.max.x - out.grid_box.min.x) / out.cell_mm)), 0, out.nx - 1);
    y0 = std::clamp(static_cast<int>(std::floor((b.min.y - out.grid_box.min.y) / out.cell_mm)), 0, out.ny - 1);
    y1 = std::clamp(static_cast<int>(std::floor((b.max.y - out.grid_box.min.y) / out.cell_mm)), 0, out.ny - 1);
  };
  std::vector<std::uint32_t> counts(static_cast<size_t>(out.nx) * out.ny + 1, 0);
  for (const RenderTri& t : out.tris) {
    int x0, x1, y0, y1;
    cell_range(t, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) ++counts[static_cast<size_t>(y * out.nx + x) + 1];
  }
  for (size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
  out.cell_start = counts;
  out.cell_tris.resize(counts.back());
  std::vector<std::uint32_t> fill(counts.begin(), counts.end() - 1);
  for (size_t i = 0; i < out.tris.size(); ++i) {
    int x0, x1, y0, y1;
    cell_range(out.tris[i], x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        out.cell_tris[fill[static_cast<size_t>(y * out.nx + x)]++] = static_cast<std::uint32_t>(i);
  }
}

}  // namespace tp::geometry::internal
