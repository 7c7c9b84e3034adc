// tests/geometry/continuity/continuity_test.cpp: the continuity measurement on the hand-made
// eight-gore skirt: small for a correct renderer, large when a piece's print is shifted.
#include "geometry/continuity/continuity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/design/make_piece_renderer.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

Design ramp_design() {
  CylindricalProjection c;
  c.image = test::make_image(256, 128, [](int x, int y) {
    const double a = 2 * std::numbers::pi * x / 256.0;
    return Rgba8{static_cast<std::uint8_t>(128 + 100 * std::sin(3 * a)), static_cast<std::uint8_t>(2 * y),
                 static_cast<std::uint8_t>(128 + 100 * std::cos(a)), 255};
  });
  Design d;
  d.layers.push_back({"ramp", 1.0, c});
  return d;
}

// Renders one piece's print shifted by a few millimetres: a seam that is not continuous.
class ShiftedRenderer : public PieceRenderer {
 public:
  ShiftedRenderer(const PieceRenderer& inner, int piece, Vec2 shift) : inner_(inner), piece_(piece), shift_(shift) {}
  int piece_count() const override { return inner_.piece_count(); }
  const Polygon& cut_outline_mm(int p) const override { return inner_.cut_outline_mm(p); }
  void render(int p, const Affine2& m, int w, int h, Rgba8* out, std::ptrdiff_t stride) const override {
    inner_.render(p, p == piece_ ? Affine2::translation(shift_).compose(m) : m, w, h, out, stride);
  }

 private:
  const PieceRenderer& inner_;
  int piece_;
  Vec2 shift_;
};

TEST(Continuity, SeamsAndAllowancesOfACylindricalProjectionMatch) {
  auto g = test::gore_skirt();
  Finishing f;
  f.marks = MarkMode::kNone;
  auto r = make_piece_renderer(g.pattern, g.garment, ramp_design(), f);
  ASSERT_TRUE(r) << r.error().what();
  auto rep = measure_continuity(g.pattern, g.garment, f, **r, 100);
  ASSERT_TRUE(rep) << rep.error().what();
  EXPECT_EQ(rep->seam_list.size(), 8u);
  EXPECT_GT(rep->seams.samples, 1000u);
  EXPECT_LT(rep->seams.mean, 0.5);
  EXPECT_LT(rep->seams.p95, 1.0);
  EXPECT_GT(rep->allowance.samples, 1000u);
  EXPECT_LT(rep->allowance.p95, 2.5);
  // Both categories are measured: side seams copy the partner, hem and waist mirror.
  bool cat1 = false, cat2 = false;
  for (const auto& a : rep->allowance_list) (a.category == 1 ? cat1 : cat2) = true;
  EXPECT_TRUE(cat1);
  EXPECT_TRUE(cat2);
  const std::string json = continuity_json(*rep);
  EXPECT_NE(json.find("\"seams\""), std::string::npos);
  EXPECT_NE(json.find("\"de00_p95\""), std::string::npos);
}

TEST(Continuity, AShiftedPieceShowsAsASeamDifference) {
  auto g = test::gore_skirt();
  Finishing f;
  f.marks = MarkMode::kNone;
  auto r = make_piece_renderer(g.pattern, g.garment, ramp_design(), f);
  ASSERT_TRUE(r) << r.error().what();
  ShiftedRenderer shifted(**r, 2, {20, 0});
  auto rep = measure_continuity(g.pattern, g.garment, f, shifted, 100);
  ASSERT_TRUE(rep) << rep.error().what();
  double worst = 0;
  for (const auto& s : rep->seam_list)
    if (s.piece_a == "gore2" || s.piece_b == "gore2") worst = std::max(worst, s.de00.mean);
  EXPECT_GT(worst, 3.0);
}

TEST(Continuity, RejectsABadDpi) {
  auto g = test::gore_skirt();
  auto r = make_piece_renderer(g.pattern, g.garment, ramp_design(), Finishing{});
  ASSERT_TRUE(r);
  auto rep = measure_continuity(g.pattern, g.garment, Finishing{}, **r, 0);
  ASSERT_FALSE(rep);
  EXPECT_NE(rep.error().message.find("dpi"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
