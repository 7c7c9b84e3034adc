// geometry/nesting/internal/overlap.cpp: segment tests, polygon collision and the pole overlap
// proxy. This is the inner loop of the search: no allocation, early exits first.
#include "geometry/nesting/internal/overlap.h"

#include <cmath>
#include <numbers>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "geometry/nesting/internal/poles.h"

namespace tp::geometry::nesting {
namespace {

inline double orient(Vec2 a, Vec2 b, Vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Segments (p1,p2) and (q1,q2) share a point. Their boxes are known to touch, which settles the
// collinear case.
inline bool segments_touch(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0)) return false;
  const double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  if ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)) return false;
  return true;
}

inline bool edge_touches_box(Vec2 a, Vec2 b, const Box2& box) {
  return lo(a.x, b.x) <= box.max.x && hi(a.x, b.x) >= box.min.x && lo(a.y, b.y) <= box.max.y &&
         hi(a.y, b.y) >= box.min.y;
}

// Padding lanes sit this far away with radius 0, so they add exactly 0.
constexpr float kFarAway = 1e15f;

bool point_in(const PolyRef& p, Vec2 q) {
  bool inside = false;
  for (int i = 0, j = p.n - 1; i < p.n; j = i++) {
    const Vec2 a = p.pts[i], b = p.pts[j];
    if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace

bool polygons_collide(const PolyRef& a, const PolyRef& b, std::vector<int>& ea, std::vector<int>& eb) {
  // Only edges that reach into the common box can meet.
  Box2 common;
  common.min = {hi(a.box.min.x, b.box.min.x), hi(a.box.min.y, b.box.min.y)};
  common.max = {lo(a.box.max.x, b.box.max.x), lo(a.box.max.y, b.box.max.y)};
  ea.clear();
  eb.clear();
  for (int i = 0; i < a.n; ++i) {
    const int j = i + 1 == a.n ? 0 : i + 1;
    if (edge_touches_box(a.pts[i], a.pts[j], common)) ea.push_back(i);
  }
  if (!ea.empty()) {
    for (int i = 0; i < b.n; ++i) {
      const int j = i + 1 == b.n ? 0 : i + 1;
      if (edge_touches_box(b.pts[i], b.pts[j], common)) eb.push_back(i);
    }
    for (int i : ea) {
      const Vec2 p1 = a.pts[i], p2 = a.pts[i + 1 == a.n ? 0 : i + 1];
      const double xmin = lo(p1.x, p2.x), xmax = hi(p1.x, p2.x);
      const double ymin = lo(p1.y, p2.y), ymax = hi(p1.y, p2.y);
      for (int k : eb) {
        const Vec2 q1 = b.pts[k], q2 = b.pts[k + 1 == b.n ? 0 : k + 1];
        if (hi(q1.x, q2.x) < xmin || lo(q1.x, q2.x) > xmax || hi(q1.y, q2.y) < ymin || lo(q1.y, q2.y) > ymax)
          continue;
        if (segments_touch(p1, p2, q1, q2)) return true;
      }
    }
  }
  // Boundaries apart: they collide only if one contains the other.
  if (box_within(a.box, b.box) && point_in(b, a.inner)) return true;
  if (box_within(b.box, a.box) && point_in(a, b.inner)) return true;
  return false;
}

void PoleSoA::assign(const std::vector<Circle>& poles) {
  const size_t n = (poles.size() + 3) / 4 * 4;
  x.assign(n, kFarAway);
  y.assign(n, kFarAway);
  r.assign(n, 0.0f);
  for (size_t i = 0; i < poles.size(); ++i) {
    x[i] = static_cast<float>(poles[i].c.x);
    y[i] = static_cast<float>(poles[i].c.y);
    r[i] = static_cast<float>(poles[i].r);
  }
}

double overlap_proxy(const PoleSoA& a, const std::vector<Circle>& b, Vec2 shift_b, double eps, double limit) {
  const size_t n = a.x.size();
  const float e = static_cast<float>(eps), e2 = e * e;
#if defined(__SSE2__)
  const __m128 ve = _mm_set1_ps(e), ve2 = _mm_set1_ps(e2), v2e = _mm_set1_ps(2 * e);
  __m128 sum = _mm_setzero_ps();
  for (const Circle& q : b) {
    const __m128 qx = _mm_set1_ps(static_cast<float>(q.c.x + shift_b.x));
    const __m128 qy = _mm_set1_ps(static_cast<float>(q.c.y + shift_b.y));
    const __m128 qr = _mm_set1_ps(static_cast<float>(q.r));
    for (size_t i = 0; i < n; i += 4) {
      const __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(&a.x[i]));
      const __m128 dy = _mm_sub_ps(qy, _mm_loadu_ps(&a.y[i]));
      const __m128 ar = _mm_loadu_ps(&a.r[i]);
      const __m128 d = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)));
      const __m128 pd = _mm_sub_ps(_mm_add_ps(qr, ar), d);
      // Penetrating pairs count their depth; the others a tail that decays with the distance.
      const __m128 tail = _mm_div_ps(ve2, _mm_sub_ps(v2e, pd));
      const __m128 deep = _mm_cmpge_ps(pd, ve);
      const __m128 depth = _mm_or_ps(_mm_and_ps(deep, pd), _mm_andnot_ps(deep, tail));
      sum = _mm_add_ps(sum, _mm_mul_ps(depth, _mm_min_ps(qr, ar)));
    }
    // The largest poles come first: checking the bound after each one rejects bad samples early.
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, sum);
    const double partial =
        std::numbers::pi * ((static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]));
    if (partial > limit) return partial;
  }
  alignas(16) float lanes[4];
  _mm_store_ps(lanes, sum);
  const double total = (static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]);
#else
  float lanes[4] = {0, 0, 0, 0};
  for (const Circle& q : b) {
    const float qx = static_cast<float>(q.c.x + shift_b.x), qy = static_cast<float>(q.c.y + shift_b.y);
    const float qr = static_cast<float>(q.r);
    for (size_t i = 0; i < n; ++i) {
      const float dx = qx - a.x[i], dy = qy - a.y[i];
      const float pd = qr + a.r[i] - std::sqrt(dx * dx + dy * dy);
      const float depth = pd >= e ? pd : e2 / (2 * e - pd);
      lanes[i % 4] += depth * (qr < a.r[i] ? qr : a.r[i]);
    }
    const double partial =
        std::numbers::pi * ((static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]));
    if (partial > limit) return partial;
  }
  const double total = (static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]);
#endif
  return std::numbers::pi * total;
}

}  // namespace tp::geometry::nesting
