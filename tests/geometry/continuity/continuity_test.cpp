// tests/geometry/continuity/continuity_test.cpp: the continuity measurement on the hand-made
// eight-gore skirt: small for a correct renderer, large when a piece's print is shifted.
#include "geometry/continuity/continuity.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
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

// The gore skirt with the ramp printed on it, no marks: what most tests here measure.
class Continuity : public ::testing::Test {
 protected:
  void SetUp() override {
    auto made = make_piece_renderer(g.pattern, g.garment, ramp_design(), f);
    ASSERT_TRUE(made) << made.error().what();
    r = std::move(*made);
  }
  test::TestGarment g = test::gore_skirt();
  Finishing f = [] {
    Finishing x;
    x.marks = MarkMode::kNone;
    return x;
  }();
  std::unique_ptr<PieceRenderer> r;
};

TEST_F(Continuity, SeamsAndAllowancesOfACylindricalProjectionMatch) {
  auto rep = measure_continuity(g.pattern, g.garment, f, *r, 100);
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

TEST_F(Continuity, AShiftedPieceShowsAsASeamDifference) {
  ShiftedRenderer shifted(*r, 2, {20, 0});
  auto rep = measure_continuity(g.pattern, g.garment, f, shifted, 100);
  ASSERT_TRUE(rep) << rep.error().what();
  double worst = 0;
  for (const auto& s : rep->seam_list)
    if (s.piece_a == "gore2" || s.piece_b == "gore2") worst = std::max(worst, s.de00.mean);
  EXPECT_GT(worst, 3.0);
}

// The pairs are compared on several threads and gathered in order: the same report, worst
// samples and their order included, for any thread count.
TEST_F(Continuity, TheReportIsTheSameForAnyThreadCount) {
  ShiftedRenderer shifted(*r, 2, {20, 0});  // differences to rank
  std::vector<ContinuityReport> reports;
  for (int threads : {1, 2, 3}) {
    ContinuityOptions o;
    o.threads = threads;
    auto rep = measure_continuity(g.pattern, g.garment, f, shifted, 100, o);
    ASSERT_TRUE(rep) << rep.error().what();
    reports.push_back(std::move(*rep));
  }
  ASSERT_GT(reports[0].seams.max, 3.0);
  ASSERT_EQ(reports[0].worst_seam_samples.size(), 8u);
  for (size_t i = 1; i < reports.size(); ++i) {
    EXPECT_EQ(continuity_json(reports[i]), continuity_json(reports[0])) << "threads " << i + 1;
    for (auto list : {&ContinuityReport::worst_seam_samples, &ContinuityReport::worst_allowance_samples}) {
      const auto &a = reports[0].*list, &b = reports[i].*list;
      ASSERT_EQ(a.size(), b.size());
      for (size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].de00, b[k].de00) << k;
        EXPECT_EQ(a[k].piece_a, b[k].piece_a) << k;
        EXPECT_EQ(a[k].at_a_mm.x, b[k].at_a_mm.x) << k;
        EXPECT_EQ(a[k].at_b_mm.y, b[k].at_b_mm.y) << k;
      }
    }
  }
}

// The printed-seam measure reads the same sample pairs through a sampler of its own (host: the
// printed fabric where the marker put each piece); here one that renders as the contone measure does.
TEST_F(Continuity, ASamplerReadsTheSamePairsAndMaySkipSome) {
  auto contone = measure_continuity(g.pattern, g.garment, f, *r, 100);
  ASSERT_TRUE(contone) << contone.error().what();
  const double mm_per_px = 25.4 / 100;
  ContinuityOptions o;
  std::atomic<int> calls = 0;  // the sampler is called from every thread
  o.sample = [&](int piece, Vec2 p) -> std::optional<Lab> {
    ++calls;
    Rgba8 px{};
    r->render(piece, Affine2{mm_per_px, 0, p.x - 0.5 * mm_per_px, 0, -mm_per_px, p.y + 0.5 * mm_per_px}, 1, 1, &px, 1);
    return srgb_over_white_to_lab(px);
  };
  auto same = measure_continuity(g.pattern, g.garment, f, *r, 100, o);
  ASSERT_TRUE(same) << same.error().what();
  EXPECT_GT(calls, 0);
  EXPECT_EQ(same->seams.samples, contone->seams.samples);
  EXPECT_NEAR(same->seams.mean, contone->seams.mean, 1e-9);
  EXPECT_EQ(same->allowance.samples, contone->allowance.samples);
  EXPECT_NEAR(same->allowance.p95, contone->allowance.p95, 1e-9);

  // A piece the sampler cannot read (not on the fabric image) drops its pairs, and its seams.
  o.sample = [&](int piece, Vec2 p) -> std::optional<Lab> {
    if (piece == 2) return std::nullopt;
    return Lab{50 + 0 * p.x, 0, 0};
  };
  auto partial = measure_continuity(g.pattern, g.garment, f, *r, 100, o);
  ASSERT_TRUE(partial) << partial.error().what();
  EXPECT_LT(partial->seams.samples, contone->seams.samples);
  EXPECT_GT(partial->seams.samples, 0u);
  EXPECT_EQ(partial->seams.max, 0.0);
  for (const auto& s : partial->seam_list) EXPECT_TRUE(s.piece_a != "gore2" && s.piece_b != "gore2") << s.piece_a;
}

TEST_F(Continuity, RejectsABadDpi) {
  auto rep = measure_continuity(g.pattern, g.garment, f, *r, 0);
  ASSERT_FALSE(rep);
  EXPECT_NE(rep.error().message.find("dpi"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
