// geometry/common/vec.h: plain 2D/3D vectors and 2D affine maps (millimetres unless named otherwise).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace tp::geometry {

struct Vec2 {
  double x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  Vec2& operator+=(Vec2 b) { x += b.x; y += b.y; return *this; }
  Vec2& operator-=(Vec2 b) { x -= b.x; y -= b.y; return *this; }
  friend bool operator==(Vec2 a, Vec2 b) = default;
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z of the 3D cross product: > 0 when b is counter-clockwise from a.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline Vec2 normalized(Vec2 a) { double n = norm(a); return n > 0 ? a / n : Vec2{}; }
/// a rotated by +90 degrees.
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator*(double s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  Vec3& operator+=(Vec3 b) { x += b.x; y += b.y; z += b.z; return *this; }
  Vec3& operator-=(Vec3 b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
  friend bool operator==(Vec3 a, Vec3 b) = default;
};

inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) { double n = norm(a); return n > 0 ? a / n : Vec3{}; }

/// 2D affine map p -> (a*x + b*y + c, d*x + e*y + f).
struct Affine2 {
  double a = 1, b = 0, c = 0;
  double d = 0, e = 1, f = 0;

  Vec2 apply(Vec2 p) const { return {a * p.x + b * p.y + c, d * p.x + e * p.y + f}; }
  /// The linear part applied to a direction (no translation).
  Vec2 apply_linear(Vec2 v) const { return {a * v.x + b * v.y, d * v.x + e * v.y}; }
  double determinant() const { return a * e - b * d; }
  /// Inverse map; the caller guarantees a non-zero determinant.
  Affine2 inverse() const {
    double det = determinant();
    Affine2 r;
    r.a = e / det; r.b = -b / det;
    r.d = -d / det; r.e = a / det;
    r.c = -(r.a * c + r.b * f);
    r.f = -(r.d * c + r.e * f);
    return r;
  }
  /// (this ∘ o)(p) = this(o(p)).
  Affine2 compose(const Affine2& o) const {
    Affine2 r;
    r.a = a * o.a + b * o.d; r.b = a * o.b + b * o.e; r.c = a * o.c + b * o.f + c;
    r.d = d * o.a + e * o.d; r.e = d * o.b + e * o.e; r.f = d * o.c + e * o.f + f;
    return r;
  }
  static Affine2 translation(Vec2 t) { return {1, 0, t.x, 0, 1, t.y}; }
  static Affine2 scale(double sx, double sy) { return {sx, 0, 0, 0, sy, 0}; }
  static Affine2 rotation_deg(double deg) {
    double r = deg * std::numbers::pi / 180.0, cs = std::cos(r), sn = std::sin(r);
    return {cs, -sn, 0, sn, cs, 0};
  }
};

/// A simple closed polygon (last vertex joins the first; not repeated), in mm.
using Polygon = std::vector<Vec2>;

/// Signed area in mm²: positive for counter-clockwise vertex order.
inline double signed_area(const Polygon& poly) {
  double s = 0;
  for (size_t i = 0, n = poly.size(); i < n; ++i) s += cross(poly[i], poly[(i + 1) % n]);
  return 0.5 * s;
}

/// Whether p lies inside the polygon (even-odd crossing rule; points on an edge may go either way).
inline bool point_in_polygon(const Polygon& poly, Vec2 p) {
  bool inside = false;
  for (size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

/// Axis-aligned box; empty when min > max.
struct Box2 {
  Vec2 min{1e300, 1e300}, max{-1e300, -1e300};
  void add(Vec2 p) {
    min.x = std::fmin(min.x, p.x); min.y = std::fmin(min.y, p.y);
    max.x = std::fmax(max.x, p.x); max.y = std::fmax(max.y, p.y);
  }
  bool empty() const { return min.x > max.x || min.y > max.y; }
  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
};

inline Box2 bounds(const Polygon& poly) {
  Box2 b;
  for (Vec2 p : poly) b.add(p);
  return b;
}

}  // namespace tp::geometry
