// tests/geometry/sewing/xpbd_garmentcode_2021_slow_test.cpp: GarmentCode 2021's two-panel skirt on
// its SMPL T-pose body (from ../shared/data) sews closed, untangled and outside the body with XPBD at
// 10,000 vertices (its side seams started crossed, 12 mm open and 278 pairs, before the panels
// rolled round the body were fitted side by side).
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/body/body_sdf.h"
#include "geometry/body/load_body_obj.h"
#include "geometry/garment/distortion.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/import/garmentcode.h"
#include "geometry/sewing/sew_garment.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

TEST(XpbdGarmentCode2021, SkirtTwoPanelsSewsOnItsBody) {
  const auto data = tp::test::shared_data_dir() / "garmentcode-2021";
  auto pattern = load_garmentcode(data / "skirt_2_panels.json");
  ASSERT_TRUE(pattern) << pattern.error().what();
  auto mesh = load_body_obj((data / "f_smpl_template.obj").string(), 1000);
  ASSERT_TRUE(mesh) << mesh.error().what();
  auto body = BodySdf::build(std::move(*mesh));
  ASSERT_TRUE(body) << body.error().what();
  SewOptions o;
  o.solver = SewSolver::kXpbd;
  o.target_edge_mm = target_edge_for_vertex_count(*pattern, 10000);
  o.threads = 2;
  SewStats st;
  auto g = sew_garment(*pattern, *body, o, &st);
  ASSERT_TRUE(g) << g.error().what();
  ASSERT_EQ(st.stitch_gap_mm.size(), pattern->stitches.size());
  for (size_t s = 0; s < st.stitch_gap_mm.size(); ++s) {
    const auto& gaps = st.stitch_gap_mm[s];
    const double worst = gaps.empty() ? 0 : *std::max_element(gaps.begin(), gaps.end());
    EXPECT_LE(worst, 1.0) << "stitch " << s << " open";
  }
  EXPECT_EQ(count_self_intersections(*g), 0);
  const DistortionReport r = measure_distortion(*pattern, *g, &*body);
  EXPECT_EQ(r.inside_body, 0);
  EXPECT_LE(r.strain_p95, 0.05);
}

}  // namespace
}  // namespace tp::geometry
