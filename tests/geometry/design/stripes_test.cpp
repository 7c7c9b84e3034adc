// tests/geometry/design/stripes_test.cpp: horizontal stripes projected cylindrically on the
// eight-gore skirt stay at constant height around the body (straight) and meet across every seam.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/textures.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

constexpr double kDpi = 200;
constexpr double kStripe_mm = 25;  // each stripe's height on the garment

Rgba8 pixel_at(const PieceRenderer& r, int piece, Vec2 p) {
  const double s = 25.4 / kDpi;
  Rgba8 px{};
  r.render(piece, Affine2{s, 0, p.x - 0.5 * s, 0, -s, p.y + 0.5 * s}, 1, 1, &px, 1);
  return px;
}

// 3D height of a point of a gore chart (the gore is an exact planar facet of the garment).
double height_at(const test::TestGarment& g, int piece, Vec2 p) {
  const GarmentPiece& gp = g.garment.pieces[static_cast<size_t>(piece)];
  for (const auto& t : gp.mesh.triangles) {
    const Vec2 a = gp.mesh.vertices_mm[static_cast<size_t>(t[0])], b = gp.mesh.vertices_mm[static_cast<size_t>(t[1])],
               c = gp.mesh.vertices_mm[static_cast<size_t>(t[2])];
    const double det = cross(b - a, c - a);
    const double wb = cross(p - a, c - a) / det, wc = cross(b - a, p - a) / det, wa = 1 - wb - wc;
    if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
    auto y = [&](int i) { return g.garment.vertices_mm[static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(i)])].y; };
    return wa * y(t[0]) + wb * y(t[1]) + wc * y(t[2]);
  }
  return NAN;
}

// Positions along a chart polyline (a -> b) where the stripe colour flips, by bisection to 0.01 mm.
std::vector<Vec2> flips(const PieceRenderer& r, int piece, Vec2 a, Vec2 b) {
  std::vector<Vec2> out;
  const double len = norm(b - a), step = 0.5;
  auto dark = [&](Vec2 p) { return pixel_at(r, piece, p).r < 128; };
  bool prev = dark(a);
  for (double s = step; s <= len; s += step) {
    const Vec2 p = a + (b - a) * (s / len);
    const bool cur = dark(p);
    if (cur == prev) continue;
    double lo = s - step, hi = s;
    for (int i = 0; i < 12; ++i) {
      const double mid = 0.5 * (lo + hi);
      (dark(a + (b - a) * (mid / len)) == prev ? lo : hi) = mid;
    }
    out.push_back(a + (b - a) * (0.5 * (lo + hi) / len));
    prev = cur;
  }
  return out;
}

TEST(Stripes, StayAtConstantHeightAndMeetAcrossEverySeam) {
  auto g = test::gore_skirt();
  CylindricalProjection c;
  c.image = std::make_shared<const ImageRgba8>(stripes(64, 256, 8, false, {{20, 20, 20, 255}, {240, 240, 240, 255}}));
  c.tile_height_mm = 8 * kStripe_mm;
  Design d;
  d.layers.push_back({"stripes", 1.0, c});
  Finishing f;
  f.marks = MarkMode::kNone;
  auto r = make_piece_renderer(g.pattern, g.garment, d, f);
  ASSERT_TRUE(r) << r.error().what();
  // Error budget: a stripe edge is located to within about one pixel (0.127 mm at 200 dpi) plus
  // the anti-aliasing of the stripe image's own edges.
  const double budget_mm = 25.4 / kDpi + 0.15;
  for (int k = 0; k < 8; ++k) {
    const auto& right = g.pattern.pieces[static_cast<size_t>(k)].edges[1].points_mm;
    const auto& left = g.pattern.pieces[static_cast<size_t>((k + 1) % 8)].edges[3].points_mm;
    // Along the seam, both sides flip at the same points (the seam runs up on one piece, down on
    // the other) and every flip is at a stripe boundary height.
    const auto fa = flips(**r, k, right[0] + Vec2{-0.05, 0}, right[1] + Vec2{-0.05, 0});
    const auto fb = flips(**r, (k + 1) % 8, left[1] + Vec2{0.05, 0}, left[0] + Vec2{0.05, 0});
    ASSERT_EQ(fa.size(), fb.size()) << "seam " << k;
    EXPECT_GE(fa.size(), 20u);
    for (size_t i = 0; i < fa.size(); ++i) {
      const double ha = height_at(g, k, fa[i] + Vec2{-0.1, 0}), hb = height_at(g, (k + 1) % 8, fb[i] + Vec2{0.1, 0});
      EXPECT_NEAR(ha, hb, budget_mm) << "seam " << k << " flip " << i;
      const double rem = std::remainder(ha, kStripe_mm);
      EXPECT_NEAR(rem, 0, budget_mm) << "seam " << k << " height " << ha;
    }
    // Straight: across the middle of the gore the stripes sit at the same heights.
    const Vec2 mid_hem{0, 0}, mid_waist{0, right[1].y};
    for (Vec2 p : flips(**r, k, mid_hem + Vec2{0, 1}, mid_waist - Vec2{0, 1}))
      EXPECT_NEAR(std::remainder(height_at(g, k, p), kStripe_mm), 0, budget_mm) << "gore " << k;
  }
}

}  // namespace
}  // namespace tp::geometry
