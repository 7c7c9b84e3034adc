// geometry/design/raster/render_window.cpp: the renderer's hot loop.
//
// Time budget: the RIP must reach 500 m²/h at 600 dpi on 2 cores including this rendering
// (about 78 Mpx/s for everything), so a projected layer must render well above that. Per call:
// find the window's triangles in the piece grid and set up each one's per-pixel gradients and
// filter once; per row: the outline's coverage, then one span per triangle sampled by the
// integer span sampler, then one compositing pass. No allocation in steady state (thread-local
// scratch), no per-pixel virtual call, no per-pixel branch on the filter kind.
#include "geometry/design/raster/render_window.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "geometry/common/tolerances.h"
#include "geometry/design/raster/span_sampler.h"

namespace tp::geometry::internal {
namespace {

// Gradients of an affine function of piece mm, per pixel: f(i+0.5, j+0.5) = base + dx*i + dy*j.
struct PixelLinear {
  double base = 0, dx = 0, dy = 0;
  double at(int i, int j) const { return base + dx * i + dy * j; }
};

PixelLinear to_pixels(const Linear2& f, const Affine2& m) {
  PixelLinear p;
  p.dx = f.ax * m.a + f.ay * m.d;
  p.dy = f.ax * m.b + f.ay * m.e;
  // Value at the centre of pixel (0, 0).
  const Vec2 c = m.apply({0.5, 0.5});
  p.base = f.at(c);
  return p;
}

// A triangle edge in pixel space, endpoints ordered by y (then x) so both triangles sharing the
// edge compute identical crossings.
struct EdgePx {
  double x0, y0, y1, slope;  // x at y = x0 + (y - y0) * slope, for y in [y0, y1)
};

struct TriSetup {
  std::uint32_t tri = 0;
  int row0 = 0, row1 = 0;     // rows whose centre may lie inside
  EdgePx edges[3];
  int n_edges = 0;
  std::uint32_t entry0 = 0, entry1 = 0;  // range in Scratch::entries
};

struct EntrySetup {
  const TriLayer* layer = nullptr;
  PixelLinear u, v, w;
  SpanFilter filter;
  PixelLinear x3, y3, z3;  // strokes and occlusion
};

struct OutlineEdge {
  double x0, y0, x1, y1;  // pixel space, y0 < y1 after ordering; dir keeps the winding
  double dir;
};

struct MarkPx {
  Vec2 a, b;
  double half_width_px;
  double ymin, ymax;
};

struct Scratch {
  std::vector<std::uint32_t> candidates;
  std::vector<TriSetup> tris;
  std::vector<EntrySetup> entries;
  std::vector<OutlineEdge> edges;
  std::vector<MarkPx> marks;
  std::vector<float> acc;
  std::vector<std::uint8_t> cov, written, prev_written;
  std::vector<std::uint32_t> colour, prev_colour, tmp;
};

thread_local Scratch g_scratch;
thread_local std::vector<const OutlineEdge*> g_active;
thread_local std::vector<const StrokeSegment*> g_near_segments;
thread_local std::vector<std::uint32_t> g_live_tris;
thread_local std::vector<std::pair<int, int>> g_touched;

EdgePx make_edge(Vec2 a, Vec2 b) {
  if (a.y > b.y || (a.y == b.y && a.x > b.x)) std::swap(a, b);
  return {a.x, a.y, b.y, (b.x - a.x) / (b.y - a.y)};
}

// Adds the signed area one outline edge covers in row `row` of the accumulation buffer; the cells
// it touched are [touched0, touched1) (unchanged when it touched none).
void accumulate(float* acc, int width, const OutlineEdge& e, int row, int& touched0, int& touched1) {
  const double ya = std::max(e.y0, static_cast<double>(row)), yb = std::min(e.y1, static_cast<double>(row + 1));
  if (ya >= yb) return;
  const double slope = (e.x1 - e.x0) / (e.y1 - e.y0);
  double xa = e.x0 + (ya - e.y0) * slope, xb = e.x0 + (yb - e.y0) * slope;
  if (xa > xb) std::swap(xa, xb);
  // Left of the window the edge acts at x = 0; right of it, it touches no visible pixel.
  xa = std::clamp(xa, 0.0, static_cast<double>(width));
  xb = std::clamp(xb, 0.0, static_cast<double>(width));
  const double d = e.dir * (yb - ya);
  const int c0 = static_cast<int>(xa), c1 = std::min(static_cast<int>(xb), width);
  touched0 = c0;
  touched1 = c1 + 2;
  if (xb - xa < kBoundarySlack) {
    // The coverage to the right of a piece at x within cell c: (c + 1 - x) here, the rest next.
    const double f = xa - c0;
    acc[c0] += static_cast<float>(d * (1 - f));
    acc[c0 + 1] += static_cast<float>(d * f);
    return;
  }
  const double inv = d / (xb - xa);
  for (int c = c0; c <= c1; ++c) {
    const double lo = std::max(xa, static_cast<double>(c)), hi = std::min(xb, static_cast<double>(c + 1));
    if (hi <= lo) continue;
    const double h = (hi - lo) * inv, m = 0.5 * (lo + hi) - c;
    acc[c] += static_cast<float>(h * (1 - m));
    acc[c + 1] += static_cast<float>(h * m);
  }
}

// Pixel span [i0, i1) of a triangle on the row whose centre is yc; false when none. Edges are
// closed and grown by a hair, so a centre exactly on an edge shared with a neighbour, or on a
// T-junction left by splitting one side only, always belongs to some triangle; the caller skips
// pixels an earlier triangle already claimed.
bool span(const TriSetup& t, double yc, int& i0, int& i1) {
  constexpr double kEps = 1e-7;  // pixels
  double xl = 1e300, xr = -1e300;
  for (int k = 0; k < t.n_edges; ++k) {
    const EdgePx& e = t.edges[k];
    if (yc < e.y0 - kEps || yc > e.y1 + kEps) continue;
    const double x = e.x0 + (yc - e.y0) * e.slope;
    xl = std::min(xl, x);
    xr = std::max(xr, x);
  }
  if (xl > xr) return false;
  // Pixel i is inside when its centre i + 0.5 lies in [xl, xr].
  i0 = static_cast<int>(std::ceil(xl - 0.5 - kEps));
  i1 = static_cast<int>(std::floor(xr - 0.5 + kEps)) + 1;
  return i1 > i0;
}

// Samples one layer over the span's pixels [i0, i0 + n). Only dst[k0, k1) is written; every
// other pixel of the span is transparent in this layer.
void sample_entry(const EntrySetup& es, const LayerRuntime& L, int i0, int n, int j, double pixel_mm,
                  const PieceData& piece, std::uint32_t* dst, int& k0, int& k1) {
  k0 = 0, k1 = n;
  if (L.kind == LayerRuntime::Kind::kTexture) {
    const MipImage& image = *L.texture->image;
    const double u0 = es.u.at(i0, j), v0 = es.v.at(i0, j);
    covered_range(image, es.filter, u0, v0, es.u.dx, es.v.dx, n, k0, k1);
    if (k0 >= k1) return;
    sample_span(image, es.filter, u0 + es.u.dx * k0, v0 + es.v.dx * k0, es.u.dx, es.v.dx, k1 - k0, dst + k0);
    const bool unit = (es.layer->flags & TriLayer::kUnitWeight) && L.opacity >= 1.0;
    const bool depth = es.layer->flags & TriLayer::kDepthTest;
    if (unit && !depth) return;
    if (!depth && es.w.dx == 0) {
      // One weight along the row (a flat panel, or a layer faded only across rows).
      const double w = std::clamp(es.w.at(i0, j), 0.0, 1.0) * L.opacity;
      const auto f = static_cast<std::uint32_t>(w * 256.0 + 0.5);
      if (f < 256)
        for (int k = k0; k < k1; ++k) dst[k] = scale_texel(dst[k], f);
      return;
    }
    for (int k = k0; k < k1; ++k) {
      double w = std::clamp(es.w.at(i0 + k, j), 0.0, 1.0) * L.opacity;
      if (depth) {
        const Vec3 p3{es.x3.at(i0 + k, j), es.y3.at(i0 + k, j), es.z3.at(i0 + k, j)};
        w *= L.depth->visibility(L.planar->plane_coordinates(p3));
      }
      dst[k] = scale_texel(dst[k], static_cast<std::uint32_t>(w * 256.0 + 0.5));
    }
    return;
  }
  // Brush stroke: distance from the pixel's surface point to the nearest candidate segment,
  // after dropping the candidates the whole span stays out of reach of.
  const std::uint32_t* seg = piece.stroke_segments.data() + es.layer->first;
  const auto& segments = L.stroke->segments();
  const double reach = L.stroke->radius_mm() + pixel_mm;
  const Vec3 s0{es.x3.at(i0, j), es.y3.at(i0, j), es.z3.at(i0, j)};
  const Vec3 s1{es.x3.at(i0 + n - 1, j), es.y3.at(i0 + n - 1, j), es.z3.at(i0 + n - 1, j)};
  std::vector<const StrokeSegment*>& near = g_near_segments;
  near.clear();
  for (std::uint32_t s = 0; s < es.layer->count; ++s) {
    const StrokeSegment& sg = segments[seg[s]];
    if (segment_segment_distance(s0, s1, sg.a, sg.b) < reach) near.push_back(&sg);
  }
  for (int k = 0; k < n; ++k) {
    if (near.empty()) {
      dst[k] = 0;
      continue;
    }
    const Vec3 p3{es.x3.at(i0 + k, j), es.y3.at(i0 + k, j), es.z3.at(i0 + k, j)};
    double d = reach;
    for (const StrokeSegment* sg : near) d = std::min(d, point_segment_distance(p3, sg->a, sg->b));
    const double c = d >= reach ? 0.0 : L.stroke->coverage(d, pixel_mm) * L.opacity;
    dst[k] = scale_texel(L.colour, static_cast<std::uint32_t>(c * 256.0 + 0.5));
  }
}

// composite() for a texel that is not opaque or a pixel the outline only partly covers.
[[gnu::noinline]] void composite_partial(Rgba8& o, std::uint32_t premult, std::uint32_t coverage) {
  const std::uint32_t pa = premult >> 24;
  const std::uint32_t a = (pa * coverage + 127) / 255;
  if (a == 0) return;
  std::uint32_t r = premult & 0xFF, g = (premult >> 8) & 0xFF, b = (premult >> 16) & 0xFF;
  if (pa != 255) {
    r = std::min<std::uint32_t>(255, (r * 255 + pa / 2) / pa);
    g = std::min<std::uint32_t>(255, (g * 255 + pa / 2) / pa);
    b = std::min<std::uint32_t>(255, (b * 255 + pa / 2) / pa);
  }
  if (o.a == 0 || a == 255) {
    o = {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(a)};
    return;
  }
  // Straight-alpha src-over onto a partly covered pixel.
  const double as = a / 255.0, ad = o.a / 255.0;
  const double ao = as + ad * (1 - as);
  auto mix = [&](std::uint32_t s, std::uint8_t dch) {
    return static_cast<std::uint8_t>(std::lround((s * as + dch * ad * (1 - as)) / ao));
  };
  o = {mix(r, o.r), mix(g, o.g), mix(b, o.b), static_cast<std::uint8_t>(std::lround(ao * 255))};
}

// Src-over of premultiplied texel `premult` with outline coverage 0..255 onto `o`. Inside the
// piece an opaque texel simply replaces the pixel: that case stays inline in the hot loop.
inline void composite(Rgba8& o, std::uint32_t premult, std::uint32_t coverage) {
  if (coverage == 255 && (premult >> 24) == 255) {
    o = {static_cast<std::uint8_t>(premult), static_cast<std::uint8_t>(premult >> 8),
         static_cast<std::uint8_t>(premult >> 16), 255};
    return;
  }
  composite_partial(o, premult, coverage);
}

void draw_marks(const Scratch& s, std::uint32_t colour, int j, int x0, int x1, std::uint32_t* row,
                const std::uint8_t* written) {
  const double yc = j + 0.5;
  for (const MarkPx& m : s.marks) {
    if (yc < m.ymin || yc > m.ymax) continue;
    const Vec2 ab = m.b - m.a;
    const double len2 = dot(ab, ab);
    // Columns the capsule can reach on this row.
    const int c0 = std::max(x0, static_cast<int>(std::floor(std::min(m.a.x, m.b.x) - m.half_width_px - 1)));
    const int c1 = std::min(x1, static_cast<int>(std::ceil(std::max(m.a.x, m.b.x) + m.half_width_px + 1)));
    for (int i = c0; i < c1; ++i) {
      if (!written[i]) continue;
      const Vec2 p{i + 0.5, yc};
      const double t = len2 > 0 ? std::clamp(dot(p - m.a, ab) / len2, 0.0, 1.0) : 0.0;
      const double d = norm(p - (m.a + ab * t));
      // Box-filtered edge: full inside, linear over one pixel at the border.
      const double cov = std::clamp(m.half_width_px + 0.5 - d, 0.0, 1.0);
      if (cov <= 0) continue;
      row[i] = over_texel(scale_texel(colour, static_cast<std::uint32_t>(cov * 256 + 0.5)), row[i]);
    }
  }
}

}  // namespace

void render_window(const PieceData& piece, const std::vector<LayerRuntime>& layers, const Affine2& m, int W, int H,
                   Rgba8* out, std::ptrdiff_t stride, const WindowOptions& options) {
  if (W <= 0 || H <= 0 || piece.nx == 0 || piece.cut_outline.size() < 3) return;
  const double det = m.determinant();
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return;
  const Affine2 inv = m.inverse();
  const double pixel_mm = std::sqrt(std::abs(det));
  Scratch& s = g_scratch;

  // Window bounds in piece mm, then the grid cells and triangles under them.
  Box2 wb;
  for (Vec2 c : {Vec2{0, 0}, Vec2{double(W), 0}, Vec2{0, double(H)}, Vec2{double(W), double(H)}}) wb.add(m.apply(c));
  if (wb.max.x < piece.grid_box.min.x || wb.min.x > piece.grid_box.max.x || wb.max.y < piece.grid_box.min.y ||
      wb.min.y > piece.grid_box.max.y)
    return;
  const int cx0 = std::clamp(static_cast<int>(std::floor((wb.min.x - piece.grid_box.min.x) / piece.cell_mm)), 0, piece.nx - 1);
  const int cx1 = std::clamp(static_cast<int>(std::floor((wb.max.x - piece.grid_box.min.x) / piece.cell_mm)), 0, piece.nx - 1);
  const int cy0 = std::clamp(static_cast<int>(std::floor((wb.min.y - piece.grid_box.min.y) / piece.cell_mm)), 0, piece.ny - 1);
  const int cy1 = std::clamp(static_cast<int>(std::floor((wb.max.y - piece.grid_box.min.y) / piece.cell_mm)), 0, piece.ny - 1);
  s.candidates.clear();
  for (int y = cy0; y <= cy1; ++y)
    for (int x = cx0; x <= cx1; ++x) {
      const size_t c = static_cast<size_t>(y * piece.nx + x);
      s.candidates.insert(s.candidates.end(), piece.cell_tris.begin() + piece.cell_start[c],
                          piece.cell_tris.begin() + piece.cell_start[c + 1]);
    }
  std::sort(s.candidates.begin(), s.candidates.end());
  s.candidates.erase(std::unique(s.candidates.begin(), s.candidates.end()), s.candidates.end());

  // Per-triangle setup: pixel-space edges, rows, and each printing layer's gradients and filter.
  s.tris.clear();
  s.entries.clear();
  for (std::uint32_t id : s.candidates) {
    const RenderTri& rt = piece.tris[id];
    Vec2 q[3];
    double ymin = 1e300, ymax = -1e300, xmin = 1e300, xmax = -1e300;
    for (int k = 0; k < 3; ++k) {
      q[k] = inv.apply(rt.p[static_cast<size_t>(k)]);
      ymin = std::min(ymin, q[k].y), ymax = std::max(ymax, q[k].y);
      xmin = std::min(xmin, q[k].x), xmax = std::max(xmax, q[k].x);
    }
    if (ymax < 0 || ymin > H || xmax < 0 || xmin > W) continue;
    TriSetup t;
    t.tri = id;
    t.row0 = std::max(0, static_cast<int>(std::floor(ymin - 0.5)) - 1);
    t.row1 = std::min(H, static_cast<int>(std::ceil(ymax - 0.5)) + 1);
    for (int k = 0; k < 3; ++k)
      if (q[k].y != q[(k + 1) % 3].y) t.edges[t.n_edges++] = make_edge(q[k], q[(k + 1) % 3]);
    if (t.row0 >= t.row1 || t.n_edges < 2) continue;
    t.entry0 = static_cast<std::uint32_t>(s.entries.size());
    for (std::uint32_t e = piece.layer_start[id]; e < piece.layer_start[id + 1]; ++e) {
      const TriLayer& tl = piece.layers[e];
      const LayerRuntime& L = layers[tl.layer];
      EntrySetup es;
      es.layer = &tl;
      if (L.kind == LayerRuntime::Kind::kTexture) {
        es.u = to_pixels(tl.u, m);
        es.v = to_pixels(tl.v, m);
        es.w = to_pixels(tl.w, m);
        es.filter = choose_filter(*L.texture->image, es.u.dx, es.v.dx, es.u.dy, es.v.dy, options.max_anisotropy);
      }
      if (L.kind == LayerRuntime::Kind::kStroke || (tl.flags & TriLayer::kDepthTest)) {
        es.x3 = to_pixels(rt.x3, m);
        es.y3 = to_pixels(rt.y3, m);
        es.z3 = to_pixels(rt.z3, m);
      }
      s.entries.push_back(es);
    }
    t.entry1 = static_cast<std::uint32_t>(s.entries.size());
    s.tris.push_back(t);
  }

  // Triangles enter and leave the row sweep in order of their rows.
  std::sort(s.tris.begin(), s.tris.end(), [](const TriSetup& a, const TriSetup& b) { return a.row0 < b.row0; });
  std::vector<std::uint32_t>& live = g_live_tris;
  live.clear();
  size_t next_tri = 0;

  // The cut outline in pixel space, sorted by first row for the sweep.
  s.edges.clear();
  const Polygon& outline = piece.cut_outline;
  for (size_t k = 0; k < outline.size(); ++k) {
    const Vec2 a = inv.apply(outline[k]), b = inv.apply(outline[(k + 1) % outline.size()]);
    if (a.y == b.y) continue;
    OutlineEdge e = a.y < b.y ? OutlineEdge{a.x, a.y, b.x, b.y, 1.0} : OutlineEdge{b.x, b.y, a.x, a.y, -1.0};
    if (e.y1 <= 0 || e.y0 >= H) continue;
    s.edges.push_back(e);
  }
  std::sort(s.edges.begin(), s.edges.end(), [](const OutlineEdge& a, const OutlineEdge& b) { return a.y0 < b.y0; });
  s.marks.clear();
  for (const MarkSegment& mk : piece.marks) {
    MarkPx mp{inv.apply(mk.a), inv.apply(mk.b), mk.half_width_mm / pixel_mm, 0, 0};
    mp.ymin = std::min(mp.a.y, mp.b.y) - mp.half_width_px - 1;
    mp.ymax = std::max(mp.a.y, mp.b.y) + mp.half_width_px + 1;
    if (mp.ymax < 0 || mp.ymin > H) continue;
    s.marks.push_back(mp);
  }

  const size_t wsz = static_cast<size_t>(W) + 2;
  if (s.acc.size() < wsz) {
    s.acc.assign(wsz, 0.0f);
    s.cov.resize(wsz);
    s.written.assign(wsz, 0);
    s.prev_written.assign(wsz, 0);
    s.colour.resize(wsz);
    s.prev_colour.resize(wsz);
    s.tmp.resize(wsz);
  }
  size_t next_edge = 0;
  std::vector<const OutlineEdge*>& active = g_active;
  active.clear();
  // Flags set in `written` (this row) and `prev_written` (the row above) lie in these ranges.
  int cur0 = 0, cur1 = 0, prev0 = 0, prev1 = 0;

  for (int j = 0; j < H; ++j) {
    // The row above becomes `prev`; the buffer of two rows above is cleared for this row.
    std::fill(s.prev_written.begin() + prev0, s.prev_written.begin() + prev1, 0);
    std::swap(s.written, s.prev_written);
    std::swap(s.colour, s.prev_colour);
    prev0 = cur0, prev1 = cur1;
    cur0 = cur1 = 0;

    // Triangles whose rows reach this one.
    while (next_tri < s.tris.size() && s.tris[next_tri].row0 <= j) live.push_back(static_cast<std::uint32_t>(next_tri++));
    live.erase(std::remove_if(live.begin(), live.end(), [&](std::uint32_t t) { return s.tris[t].row1 <= j; }), live.end());

    // 1. Coverage of the cut outline over this row.
    while (next_edge < s.edges.size() && s.edges[next_edge].y0 < j + 1) active.push_back(&s.edges[next_edge++]);
    active.erase(std::remove_if(active.begin(), active.end(), [j](const OutlineEdge* e) { return e->y1 <= j; }), active.end());
    std::vector<std::pair<int, int>>& touched = g_touched;
    touched.clear();
    int t1 = -1;  // last touched cell
    for (const OutlineEdge* e : active) {
      int lo = 0, hi = 0;
      accumulate(s.acc.data(), W, *e, j, lo, hi);
      if (lo >= hi) continue;
      touched.emplace_back(lo, hi);
      t1 = std::max(t1, hi - 1);
    }
    if (touched.empty()) continue;
    std::sort(touched.begin(), touched.end());
    const int t0 = touched.front().first;
    // Prefix sums give each pixel's coverage; cells at or past W only affect pixels outside.
    // Between touched cells the sum does not change: those pixels are filled, not summed.
    const int last = std::min(t1, W - 1);
    auto coverage = [](double run) { return static_cast<std::uint8_t>(std::min(1.0, std::abs(run)) * 255.0 + 0.5); };
    double run = 0;
    int i = t0;
    for (const auto& [lo, hi] : touched) {
      if (lo > i) {
        if (i <= last) std::memset(s.cov.data() + i, coverage(run), static_cast<size_t>(std::min(lo, last + 1) - i));
        i = lo;
      }
      for (; i < hi; ++i) {
        if (i <= last) {
          run += s.acc[static_cast<size_t>(i)];
          s.cov[static_cast<size_t>(i)] = coverage(run);
        }
        s.acc[static_cast<size_t>(i)] = 0;
      }
    }
    int x1 = last + 1;
    // Past the last touched cell the coverage stays what it was (inside: to the window's end).
    const std::uint8_t tail = coverage(run);
    if (tail > 0 && x1 < W) {
      std::fill(s.cov.begin() + x1, s.cov.begin() + W, tail);
      x1 = W;
    }
    const int x0 = std::min(t0, W);
    if (x0 >= x1) continue;
    cur0 = x0, cur1 = x1;

    // 2. Design colour at pixel centres, triangle by triangle.
    const double yc = j + 0.5;
    for (std::uint32_t ti : live) {
      const TriSetup& t = s.tris[ti];
      int i0, i1;
      if (!span(t, yc, i0, i1)) continue;
      i0 = std::max(i0, x0);
      i1 = std::min(i1, x1);
      // Neighbours share their boundary pixels: the first triangle keeps them.
      while (i0 < i1 && s.written[static_cast<size_t>(i0)]) ++i0;
      while (i1 > i0 && s.written[static_cast<size_t>(i1 - 1)]) --i1;
      if (i1 <= i0) continue;
      const int n = i1 - i0;
      std::uint32_t* dst = s.colour.data() + i0;
      if (t.entry0 == t.entry1) {
        std::fill(dst, dst + n, 0u);
      } else {
        for (std::uint32_t e = t.entry0; e < t.entry1; ++e) {
          const EntrySetup& es = s.entries[e];
          const LayerRuntime& L = layers[es.layer->layer];
          int k0, k1;
          if (e == t.entry0) {
            sample_entry(es, L, i0, n, j, pixel_mm, piece, dst, k0, k1);
            std::fill(dst, dst + k0, 0u);
            std::fill(dst + k1, dst + n, 0u);
          } else {
            sample_entry(es, L, i0, n, j, pixel_mm, piece, s.tmp.data(), k0, k1);
            for (int k = k0; k < k1; ++k) dst[k] = over_texel(s.tmp[static_cast<size_t>(k)], dst[k]);
          }
        }
      }
      std::memset(s.written.data() + i0, 1, static_cast<size_t>(n));
    }
    if (!s.marks.empty()) draw_marks(s, piece.mark_colour, j, x0, x1, s.colour.data(), s.written.data());

    // 3. Composite with coverage; edge pixels no triangle centre covers borrow a neighbour.
    Rgba8* orow = out + static_cast<std::ptrdiff_t>(j) * stride;
    for (int i = x0; i < x1; ++i) {
      const std::uint32_t c = s.cov[static_cast<size_t>(i)];
      if (c == 0) continue;
      std::uint32_t px;
      if (s.written[static_cast<size_t>(i)]) {
        px = s.colour[static_cast<size_t>(i)];
      } else {
        int found = -1;
        for (int d = 1; d <= 2 && found < 0; ++d) {
          if (i - d >= x0 && s.written[static_cast<size_t>(i - d)]) found = i - d;
          else if (i + d < x1 && s.written[static_cast<size_t>(i + d)]) found = i + d;
        }
        if (found >= 0) px = s.colour[static_cast<size_t>(found)];
        else if (s.prev_written[static_cast<size_t>(i)]) px = s.prev_colour[static_cast<size_t>(i)];
        else continue;
      }
      composite(orow[i], px, c);
    }
  }
  // Leave the flag buffers clean for the next call.
  std::fill(s.written.begin() + cur0, s.written.begin() + cur1, 0);
  std::fill(s.prev_written.begin() + prev0, s.prev_written.begin() + prev1, 0);
}

}  // namespace tp::geometry::internal
