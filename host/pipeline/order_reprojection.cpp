// host/pipeline/order_reprojection.cpp: body-relative re-projection of design layers between sizes.
#include "host/pipeline/order_reprojection.h"
#include "geometry/common/tolerances.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::host {

namespace {

using geometry::Vec3;

std::vector<double> landmark_heights(const geometry::DressFormLandmarks& l) {
  return {l.bottom_y, l.knee_y,   l.hip_y,      l.waist_y, l.underbust_y,
          l.bust_y,   l.armpit_y, l.shoulder_y, l.nape_y,  l.neck_top_y};
}

// A direction around the body: the section's normalised (u, v) scaled onto its superellipse.
struct SectionPoint {
  double u = 0, v = 0;  ///< normalised coordinates of the point (surface where rho == 1)
  double rho = 0;       ///< superellipse radius of the point (0 on the axis)
};

SectionPoint to_section(const geometry::TorsoSection& s, double x, double z) {
  SectionPoint p;
  const double dz = z - s.centre_z_mm;
  p.u = s.half_width_mm > 0 ? x / s.half_width_mm : 0;
  p.v = dz >= 0 ? (s.front_mm > 0 ? dz / s.front_mm : 0) : (s.back_mm > 0 ? dz / s.back_mm : 0);
  p.rho = std::pow(std::pow(std::abs(p.u), s.exponent) + std::pow(std::abs(p.v), s.exponent), 1 / s.exponent);
  return p;
}

// The (x, z) of normalised (u, v) in section `s`, v measured against front or back.
std::pair<double, double> from_section(const geometry::TorsoSection& s, double u, double v) {
  return {u * s.half_width_mm, s.centre_z_mm + v * (v >= 0 ? s.front_mm : s.back_mm)};
}

// The superellipse parameter of a direction (us, vs) on the unit section: x = a sgn(c)|c|^(2/n).
double section_angle(double us, double vs, double n) {
  const double c = std::copysign(std::pow(std::abs(us), n / 2), us);
  const double sn = std::copysign(std::pow(std::abs(vs), n / 2), vs);
  return std::atan2(sn, c);
}

std::pair<double, double> section_at(const geometry::TorsoSection& s, double th) {
  const double c = std::cos(th), sn = std::sin(th);
  return {
      s.half_width_mm * std::copysign(std::pow(std::abs(c), 2 / s.exponent), c),
      s.centre_z_mm + (sn >= 0 ? s.front_mm : s.back_mm) * std::copysign(std::pow(std::abs(sn), 2 / s.exponent), sn)};
}

constexpr double kArcStep = 2 * std::numbers::pi / 2048;

// Signed arc length along section `s` from parameter t0 to t1 (t1 < t0: negative).
double arc_length(const geometry::TorsoSection& s, double t0, double t1) {
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(t1 - t0) / kArcStep)));
  double len = 0;
  auto prev = section_at(s, t0);
  for (int i = 1; i <= steps; ++i) {
    const auto p = section_at(s, t0 + (t1 - t0) * i / steps);
    len += std::hypot(p.first - prev.first, p.second - prev.second);
    prev = p;
  }
  return t1 >= t0 ? len : -len;
}

// The parameter reached from t0 by walking `length` mm along section `s` (negative: backwards).
double walk_arc(const geometry::TorsoSection& s, double t0, double length) {
  const double dir = length >= 0 ? 1 : -1;
  double walked = 0, t = t0;
  auto prev = section_at(s, t);
  for (int i = 0; i < 4096; ++i) {
    const double tn = t + dir * kArcStep;
    const auto p = section_at(s, tn);
    const double step = std::hypot(p.first - prev.first, p.second - prev.second);
    if (walked + step >= std::abs(length))
      return t + dir * kArcStep * (step > 0 ? (std::abs(length) - walked) / step : 0);
    walked += step;
    t = tn;
    prev = p;
  }
  return t;
}

}  // namespace

std::vector<Vec3> SizeMapping::map_stroke(const std::vector<Vec3>& pts) const {
  if (graded_ || pts.empty()) {
    std::vector<Vec3> out;
    for (const Vec3& p : pts) out.push_back(map_point(p));
    return out;
  }
  const Vec3& a = pts[pts.size() / 2];
  const Vec3 a_mapped = map_point(a);
  std::vector<Vec3> out;
  for (const Vec3& p : pts) {
    const geometry::TorsoSection sb = geometry::dress_form_section(base_, p.y);
    const double y = a_mapped.y + (p.y - a.y);
    const geometry::TorsoSection st = geometry::dress_form_section(target_, y);
    const SectionPoint q = to_section(sb, p.x, p.z);
    const SectionPoint qa = to_section(sb, a.x, a.z);
    if (q.rho < geometry::kSamePoint_mm || qa.rho < geometry::kSamePoint_mm) {
      out.push_back(map_point(p));
      continue;
    }
    // Around the body: the same arc length from the anchor's direction on both sections.
    const double ta = section_angle(qa.u / qa.rho, qa.v / qa.rho, sb.exponent);
    const double tp = section_angle(q.u / q.rho, q.v / q.rho, sb.exponent);
    double d = tp - ta;
    if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
    if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
    const double along = arc_length(sb, ta, ta + d);
    // The anchor's direction on the target section, as map_point finds it.
    const double us = qa.u / qa.rho, vs = qa.v / qa.rho;
    const double rt =
        std::pow(std::pow(std::abs(us), st.exponent) + std::pow(std::abs(vs), st.exponent), 1 / st.exponent);
    const double tt = walk_arc(st, section_angle(us / rt, vs / rt, st.exponent), along);
    // Off the body: the point's offset from its base surface point, kept in mm.
    const auto [bx, bz] = section_at(sb, tp);
    const auto [tx, tz] = section_at(st, tt);
    out.push_back({tx + (p.x - bx), y, tz + (p.z - bz)});
  }
  return out;
}

SizeMapping::SizeMapping(const geometry::BodyMeasurements& base, const geometry::BodyMeasurements& target, bool graded)
    : base_(base),
      target_(target),
      base_lm_(geometry::dress_form_landmarks(base)),
      target_lm_(geometry::dress_form_landmarks(target)),
      ys_base_(landmark_heights(base_lm_)),
      ys_target_(landmark_heights(target_lm_)),
      graded_(graded) {}

double SizeMapping::map_height_mm(double y) const {
  // Below the lowest and above the highest landmark: the nearest landmark's shift.
  if (y <= ys_base_.front()) return y + (ys_target_.front() - ys_base_.front());
  if (y >= ys_base_.back()) return y + (ys_target_.back() - ys_base_.back());
  for (size_t k = 1; k < ys_base_.size(); ++k) {
    if (y > ys_base_[k]) continue;
    const double span = ys_base_[k] - ys_base_[k - 1];
    const double t = span > 0 ? (y - ys_base_[k - 1]) / span : 0;
    return ys_target_[k - 1] + t * (ys_target_[k] - ys_target_[k - 1]);
  }
  return y;
}

Vec3 SizeMapping::map_point(const Vec3& p) const {
  const double y = map_height_mm(p.y);
  const geometry::TorsoSection sb = geometry::dress_form_section(base_, p.y);
  const geometry::TorsoSection st = geometry::dress_form_section(target_, y);
  const SectionPoint q = to_section(sb, p.x, p.z);
  if (graded_) {
    // The same normalised place: offsets from the axis scale with the section.
    const auto [x, z] = from_section(st, q.u, q.v);
    return {x, y, z};
  }
  if (q.rho < geometry::kSamePoint_mm) {
    const auto [x, z] = from_section(st, 0, 0);
    return {x + p.x, y, z + (p.z - sb.centre_z_mm)};
  }
  // The surface point in the same direction on both sections; the offset from it is kept in mm.
  const double us = q.u / q.rho, vs = q.v / q.rho;
  const auto [bx, bz] = from_section(sb, us, vs);
  const double rt =
      std::pow(std::pow(std::abs(us), st.exponent) + std::pow(std::abs(vs), st.exponent), 1 / st.exponent);
  const auto [tx, tz] = from_section(st, us / rt, vs / rt);
  return {tx + (p.x - bx), y, tz + (p.z - bz)};
}

double SizeMapping::girth_ratio(double y) const {
  const double gb = geometry::section_girth_mm(geometry::dress_form_section(base_, y));
  const double gt = geometry::section_girth_mm(geometry::dress_form_section(target_, map_height_mm(y)));
  return gb > 0 ? gt / gb : 1;
}

namespace {

// The centre-front surface point of the torso section at height y.
Vec3 centre_front_point(const geometry::BodyMeasurements& m, double y) {
  const geometry::TorsoSection s = geometry::dress_form_section(m, y);
  return {0, y, s.centre_z_mm + s.front_mm};
}

}  // namespace

Vec3 centre_front_bust_point(const geometry::BodyMeasurements& m) {
  return centre_front_point(m, geometry::dress_form_landmarks(m).bust_y);
}

Vec3 centre_front_hip_point(const geometry::BodyMeasurements& m) {
  return centre_front_point(m, geometry::dress_form_landmarks(m).hip_y);
}

std::vector<DesignLayerSpec> reproject_layers(const std::vector<DesignLayerSpec>& layers, const SizeMapping& map) {
  auto v3 = [](const std::array<double, 3>& a) { return Vec3{a[0], a[1], a[2]}; };
  auto arr = [](const Vec3& v) { return std::array<double, 3>{v.x, v.y, v.z}; };
  std::vector<DesignLayerSpec> out = layers;
  for (DesignLayerSpec& l : out) {
    if (l.type == "planar" || l.type == "text") {
      const double s = map.graded() ? map.girth_ratio(l.centre_mm[1]) : 1.0;
      l.centre_mm = arr(map.map_point(v3(l.centre_mm)));
      l.width_mm *= s;
      l.height_mm *= s;
      l.text_size_mm *= s;
      l.outline_mm *= s;
    } else if (l.type == "cylindrical") {
      const double y_ref = l.axis_origin_mm ? (*l.axis_origin_mm)[1] : map.base_landmarks().waist_y;
      const double s = map.graded() ? map.girth_ratio(y_ref) : 1.0;
      if (l.axis_origin_mm) l.axis_origin_mm = arr(map.map_point(v3(*l.axis_origin_mm)));
      l.tile_width_mm *= s;
      l.tile_height_mm *= s;
      l.offset_mm = {l.offset_mm[0] * s, l.offset_mm[1] * s};
    } else if (l.type == "stroke") {
      double s = 1.0;
      if (map.graded() && !l.points_mm.empty()) s = map.girth_ratio(l.points_mm.front()[1]);
      std::vector<Vec3> pts;
      for (const auto& p : l.points_mm) pts.push_back(v3(p));
      pts = map.map_stroke(pts);
      for (size_t k = 0; k < pts.size(); ++k) l.points_mm[k] = arr(pts[k]);
      l.radius_mm *= s;
    }
  }
  return out;
}

}  // namespace tp::host
