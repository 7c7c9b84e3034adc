// tests/geometry/allowance/allowance_widths_test.cpp: resolving widths and corner styles per edge.
#include "geometry/allowance/allowance_widths.h"

#include <gtest/gtest.h>

#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

TEST(ResolveAllowance, SewnHemAndOpenEdgesGetTheirDefaults) {
  auto g = test::gore_skirt(4);
  Finishing f;
  f.seam_allowance_mm = 12;
  f.hem_allowance_mm = 30;
  f.edge_allowance_mm = 8;
  auto a = resolve_allowance(g.pattern, 0, f);
  ASSERT_TRUE(a) << a.error().what();
  // Edges: hem, right (sewn), waist (open), left (sewn).
  EXPECT_EQ(a->width_mm, (std::vector<double>{30, 12, 8, 12}));
  EXPECT_TRUE(a->hem[0]);
  EXPECT_TRUE(a->sewn[1] && a->sewn[3]);
  EXPECT_FALSE(a->sewn[2]);
  // The hem mirrors the side seams' cut lines at both its corners.
  EXPECT_EQ(a->corner[0], CornerStyle::kReflectIncoming);
  EXPECT_EQ(a->corner[3], CornerStyle::kReflectOutgoing);
  EXPECT_EQ(a->corner[1], CornerStyle::kMitre);
}

TEST(ResolveAllowance, OverridesAndFoldEdges) {
  auto g = test::gore_skirt(4);
  g.pattern.pieces[1].fold_edge = 1;
  Finishing f;
  f.edge_widths.push_back({"gore0", "waist", 15});
  f.hem_edges.push_back({"gore0", "waist", 0});
  f.corners.push_back({"gore0", "right", CornerStyle::kSquare});
  auto a = resolve_allowance(g.pattern, 0, f);
  ASSERT_TRUE(a) << a.error().what();
  EXPECT_EQ(a->width_mm[2], 15);  // explicit width beats the hem default
  EXPECT_TRUE(a->hem[2]);
  EXPECT_EQ(a->corner[1], CornerStyle::kSquare);
  auto b = resolve_allowance(g.pattern, 1, f);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->width_mm[1], 0);  // cut on the fold
}

TEST(ValidateFinishing, NamesTheBadField) {
  auto g = test::gore_skirt(4);
  Finishing f;
  f.edge_widths.push_back({"gore0", "collar", 10});
  auto st = validate_finishing(g.pattern, f);
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("finishing.edge_widths[0].edge"), std::string::npos) << st.error().message;
  EXPECT_NE(st.error().message.find("collar"), std::string::npos);

  Finishing neg;
  neg.hem_allowance_mm = -3;
  auto st2 = validate_finishing(g.pattern, neg);
  ASSERT_FALSE(st2);
  EXPECT_NE(st2.error().message.find("finishing.hem_allowance_mm"), std::string::npos);

  Finishing unknown;
  unknown.corners.push_back({"sleeve", "cap", CornerStyle::kMitre});
  auto st3 = validate_finishing(g.pattern, unknown);
  ASSERT_FALSE(st3);
  EXPECT_NE(st3.error().message.find("finishing.corners[0].piece"), std::string::npos) << st3.error().message;
}

}  // namespace
}  // namespace tp::geometry
