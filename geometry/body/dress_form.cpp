// geometry/body/dress_form.cpp: dress form as a blended implicit surface, meshed by marching tetrahedra.
#include "geometry/body/dress_form.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/body/marching_tetrahedra.h"

namespace tp::geometry {
namespace {

// Blend radii of the smooth unions: armpit and shoulder, neck base.
constexpr double kArmBlendMm = 14;
constexpr double kNeckBlendMm = 18;

struct Level {
  double y;
  TorsoSection s;
};

// A section of girth `girth_mm` with the given front/back depth ratios (to the half width).
TorsoSection section_with_girth(double girth_mm, double front_ratio, double back_ratio, double exponent, double centre_z) {
  TorsoSection unit{1.0, front_ratio, back_ratio, centre_z, exponent};
  double scale = girth_mm / section_girth_mm(unit);
  return {scale, front_ratio * scale, back_ratio * scale, centre_z, exponent};
}

TorsoSection scaled(const TorsoSection& s, double width_factor, double depth_factor) {
  return {s.half_width_mm * width_factor, s.front_mm * depth_factor, s.back_mm * depth_factor, s.centre_z_mm, s.exponent};
}

std::vector<Level> torso_levels(const BodyMeasurements& m, const DressFormLandmarks& l) {
  TorsoSection hip = section_with_girth(m.hips_mm, 0.64, 0.76, 2.3, 0);
  TorsoSection waist = section_with_girth(m.waist_mm, 0.74, 0.74, 2.2, 0);
  TorsoSection underbust = section_with_girth(m.underbust_mm, 0.76, 0.70, 2.2, 0);
  TorsoSection bust = section_with_girth(m.bust_mm, 0.86, 0.64, 2.2, 0);
  TorsoSection armpit = section_with_girth(m.bust_mm * 0.94, 0.68, 0.66, 2.4, -5);
  double shoulder_a = m.shoulder_width_mm / 2 - 22;
  TorsoSection shoulder{shoulder_a, 58, 62, -10, 2.6};
  double nr = l.neck_radius_mm;
  TorsoSection neck_base{nr + 14, nr + 8, nr + 10, -14, 2.0};
  return {{l.bottom_y, scaled(hip, 0.80, 0.84)},
          {l.hip_y - 0.5 * (l.hip_y - l.knee_y), scaled(hip, 0.93, 0.93)},
          {l.hip_y, hip},
          {l.waist_y, waist},
          {l.underbust_y, underbust},
          {l.bust_y, bust},
          {l.armpit_y, armpit},
          {l.shoulder_y, shoulder},
          {l.neck_top_y, neck_base}};
}

// Monotone cubic (Fritsch-Carlson) interpolation of one section field over the levels.
double pchip(const std::vector<Level>& lv, double TorsoSection::*f, double y) {
  const size_t n = lv.size();
  if (y <= lv.front().y) return lv.front().s.*f;
  if (y >= lv.back().y) return lv.back().s.*f;
  size_t k = 0;
  while (k + 2 < n && y > lv[k + 1].y) ++k;
  const auto slope = [&](size_t i) { return (lv[i + 1].s.*f - lv[i].s.*f) / (lv[i + 1].y - lv[i].y); };
  const auto tangent = [&](size_t i) {
    if (i == 0) return slope(0);
    if (i == n - 1) return slope(n - 2);
    double d0 = slope(i - 1), d1 = slope(i);
    if (d0 * d1 <= 0) return 0.0;
    double h0 = lv[i].y - lv[i - 1].y, h1 = lv[i + 1].y - lv[i].y;
    return (2 * h1 + h0 + h1 + 2 * h0) / ((2 * h1 + h0) / d0 + (h1 + 2 * h0) / d1);
  };
  double h = lv[k + 1].y - lv[k].y, t = (y - lv[k].y) / h;
  double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t), h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * (lv[k].s.*f) + h10 * h * tangent(k) + h01 * (lv[k + 1].s.*f) + h11 * h * tangent(k + 1);
}

TorsoSection section_at(const std::vector<Level>& lv, double y) {
  return {pchip(lv, &TorsoSection::half_width_mm, y), pchip(lv, &TorsoSection::front_mm, y),
          pchip(lv, &TorsoSection::back_mm, y), pchip(lv, &TorsoSection::centre_z_mm, y),
          pchip(lv, &TorsoSection::exponent, y)};
}

// The neck's axis: from inside the torso, leaning slightly forward, up past the cut.
std::array<Vec3, 2> neck_axis(const DressFormLandmarks& l) {
  return {Vec3{0, l.nape_y - 40, -16}, Vec3{0, l.nape_y + 100, -8}};
}

// Polynomial smooth minimum: a union whose crease is rounded over `k` mm.
double smooth_min(double a, double b, double k) {
  double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

// Approximate signed distance to a capsule whose radius tapers from r0 at p0 to r1 at p1.
double tapered_capsule(Vec3 p, Vec3 p0, Vec3 p1, double r0, double r1) {
  Vec3 d = p1 - p0;
  double t = std::clamp(dot(p - p0, d) / dot(d, d), 0.0, 1.0);
  return norm(p - (p0 + d * t)) - (r0 + (r1 - r0) * t);
}

}  // namespace

double section_girth_mm(const TorsoSection& s) {
  constexpr int kSamples = 256;
  double len = 0;
  Vec2 prev{};
  for (int i = 0; i <= kSamples; ++i) {
    double th = 2 * std::numbers::pi * i / kSamples, c = std::cos(th), sn = std::sin(th);
    double b = sn >= 0 ? s.front_mm : s.back_mm;
    Vec2 p{s.half_width_mm * std::copysign(std::pow(std::abs(c), 2 / s.exponent), c),
           b * std::copysign(std::pow(std::abs(sn), 2 / s.exponent), sn)};
    if (i > 0) len += norm(p - prev);
    prev = p;
  }
  return len;
}

DressFormLandmarks dress_form_landmarks(const BodyMeasurements& m) {
  DressFormLandmarks l;
  l.nape_y = m.nape_height_mm();
  l.waist_y = m.waist_height_mm();
  l.hip_y = l.waist_y - m.waist_to_hip_mm;
  l.knee_y = l.waist_y - m.waist_to_knee_mm;
  l.bottom_y = l.knee_y - 60;
  l.bust_y = l.waist_y + m.bust_above_waist_mm();
  l.underbust_y = l.bust_y - 0.2 * m.back_length_mm;
  l.armpit_y = l.nape_y - m.armscye_depth_mm;
  l.neck_radius_mm = m.neck_mm / (2 * std::numbers::pi);
  l.neck_top_y = l.nape_y + 6;
  const double slope = m.shoulder_slope_deg * std::numbers::pi / 180;
  l.shoulder_y = l.nape_y - (m.shoulder_width_mm / 2 - l.neck_radius_mm) * std::tan(slope);
  l.upper_arm_radius_mm = m.upper_arm_mm / (2 * std::numbers::pi);
  l.wrist_radius_mm = m.wrist_mm / (2 * std::numbers::pi);
  const double angle = m.arm_angle_deg * std::numbers::pi / 180;
  l.arm_joint_left = {m.shoulder_width_mm / 2 - l.upper_arm_radius_mm - 4, l.shoulder_y - 0.7 * l.upper_arm_radius_mm, -8};
  l.arm_direction_left = {std::sin(angle), -std::cos(angle), 0};
  l.arm_length_mm = m.arm_length_mm;
  l.shoulder_point_left = {m.shoulder_width_mm / 2, l.shoulder_y, -8};
  return l;
}

TorsoSection dress_form_section(const BodyMeasurements& m, double y_mm) {
  DressFormLandmarks l = dress_form_landmarks(m);
  return section_at(torso_levels(m, l), y_mm);
}

double dress_form_hps_to_waist_back_mm(const BodyMeasurements& m) {
  const DressFormLandmarks l = dress_form_landmarks(m);
  const std::vector<Level> levels = torso_levels(m, l);
  const double x = l.neck_radius_mm;  // the high point of the shoulder: beside the neck
  // The profile (y, z) at x: the neck's side on top of the shoulder, then the back from the
  // shoulder's top down to the waist.
  const auto [n0, n1] = neck_axis(l);
  std::vector<Vec2> profile{{l.neck_top_y, n0.z + (n1.z - n0.z) * (l.neck_top_y - n0.y) / (n1.y - n0.y)}};
  constexpr double kStep_mm = 1;
  for (double y = l.neck_top_y; y > l.waist_y - kStep_mm / 2; y -= kStep_mm) {
    const double at = std::max(y, l.waist_y);
    const TorsoSection s = section_at(levels, at);
    const double u = std::min(x / s.half_width_mm, 1.0);
    profile.push_back({at, s.centre_z_mm - s.back_mm * std::pow(1 - std::pow(u, s.exponent), 1 / s.exponent)});
  }
  // A tape bridges hollows: the profile's outer hull (towards -z) from the top to the waist.
  std::vector<Vec2> hull;
  for (const Vec2& c : profile) {
    while (hull.size() >= 2) {
      const Vec2 a = hull[hull.size() - 2], b = hull.back();
      if (c.x == a.x || b.y <= a.y + (c.y - a.y) * (b.x - a.x) / (c.x - a.x)) break;
      hull.pop_back();  // b lies inside the line from a to c: the tape passes over it
    }
    hull.push_back(c);
  }
  double length = 0;
  for (size_t i = 1; i < hull.size(); ++i) length += norm(hull[i] - hull[i - 1]);
  return length;
}

Result<BodyMesh> make_dress_form(const BodyMeasurements& m, const DressFormOptions& options) {
  if (auto s = validate(m); !s) return std::unexpected(s.error().with_context("dress form"));
  if (!(options.grid_spacing_mm >= 2 && options.grid_spacing_mm <= 30))
    return fail(ErrorCode::kInvalidArgument, "dress form grid spacing must be within 2..30 mm");
  const DressFormLandmarks l = dress_form_landmarks(m);
  const std::vector<Level> levels = torso_levels(m, l);
  const Vec3 arm0 = l.arm_joint_left;
  const Vec3 arm1 = arm0 + l.arm_direction_left * (l.arm_length_mm - 0.3 * l.upper_arm_radius_mm);
  const auto [neck0, neck1] = neck_axis(l);
  const double neck_cut_y = l.nape_y + 95;

  // Grid bounds: the torso's widest section, the arms' reach, a margin of 3 cells.
  const double h = options.grid_spacing_mm;
  double half_x = 0, depth = 0;
  for (const Level& lv : levels) {
    half_x = std::max(half_x, lv.s.half_width_mm);
    depth = std::max({depth, lv.s.front_mm + std::abs(lv.s.centre_z_mm), lv.s.back_mm + std::abs(lv.s.centre_z_mm)});
  }
  if (options.arms) half_x = std::max(half_x, arm1.x + l.upper_arm_radius_mm);
  ScalarGrid g;
  g.spacing_mm = h;
  g.origin_mm = {-half_x - 3 * h, l.bottom_y - 3 * h, -depth - 3 * h};
  g.nx = static_cast<int>(std::ceil(2 * (half_x + 3 * h) / h)) + 1;
  g.ny = static_cast<int>(std::ceil((neck_cut_y - l.bottom_y + 6 * h) / h)) + 1;
  g.nz = static_cast<int>(std::ceil(2 * (depth + 3 * h) / h)) + 1;
  g.values.resize(static_cast<size_t>(g.nx) * g.ny * g.nz);

  // Sections depend on height only: one per grid row.
  std::vector<TorsoSection> rows(g.ny);
  for (int j = 0; j < g.ny; ++j) rows[j] = section_at(levels, g.origin_mm.y + j * h);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        Vec3 p = g.origin_mm + Vec3{double(i), double(j), double(k)} * h;
        const TorsoSection& s = rows[j];
        double dz = p.z - s.centre_z_mm, b = dz > 0 ? s.front_mm : s.back_mm;
        double q = std::pow(std::abs(p.x) / s.half_width_mm, s.exponent) + std::pow(std::abs(dz) / b, s.exponent);
        double f = (std::pow(q, 1 / s.exponent) - 1) * std::min(s.half_width_mm, b);
        f = std::max({f, l.bottom_y - p.y, p.y - l.neck_top_y});
        double neck = std::max(tapered_capsule(p, neck0, neck1, l.neck_radius_mm, l.neck_radius_mm * 0.95), p.y - neck_cut_y);
        f = smooth_min(f, neck, kNeckBlendMm);
        if (options.arms) {
          Vec3 pm{std::abs(p.x), p.y, p.z};  // arms are mirror images
          f = smooth_min(f, tapered_capsule(pm, arm0, arm1, l.upper_arm_radius_mm, l.wrist_radius_mm), kArmBlendMm);
        }
        g.values[(static_cast<size_t>(k) * g.ny + j) * g.nx + i] = static_cast<float>(f);
      }
  BodyMesh mesh = marching_tetrahedra(g);
  mesh.name = "dress_form";
  if (mesh.triangles.empty()) return fail(ErrorCode::kInvalidArgument, "dress form: measurements give an empty surface");
  return mesh;
}

}  // namespace tp::geometry
