// tests/geometry/pattern/import/freesewing_sizes_test.cpp: FreeSewing's sizes as dress forms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/body/dress_form.h"
#include "geometry/pattern/import/freesewing_sizes.h"

namespace tp::geometry {
namespace {

// FreeSewing's hpsToWaistBack for cisFemaleAdult<size>: 395 mm at neck 340, graded at 0.65.
double freesewing_hps_to_waist_back_mm(int size) { return 395 * (1 + (size * 10.0 / 340 - 1) * 0.65); }

// What a tape measures on the meshed form from the side of the neck, on top of the shoulder,
// down the back to the waist: the back's profile in the plane x = the neck's radius, found by
// walking in from behind until inside the surface, and its outer hull (the tape bridges
// hollows). Independent of the form's sections: it reads only the mesh's distance field.
double tape_hps_to_waist_back_mm(const BodySdf& sdf, const DressFormLandmarks& l) {
  // The neck's side on top of the shoulder: the middle of the neck 20 mm above the torso.
  const auto surface_z = [&](double x, double y, double from_z, double step) {
    double z = from_z;
    while (std::abs(z) <= 400 && sdf.query({x, y, z}).distance_mm > 0) z += step;
    return z;
  };
  const double neck_z =
      0.5 * (surface_z(0, l.neck_top_y + 20, -400, 0.25) + surface_z(0, l.neck_top_y + 20, 400, -0.25));
  const double x = l.neck_radius_mm;
  std::vector<Vec2> profile{{l.neck_top_y, neck_z}};  // (y, z)
  for (double y = l.neck_top_y - 2; y > l.waist_y - 0.5; y -= 2) {
    profile.push_back({y, surface_z(x, y, -400, 0.25)});
  }
  std::vector<Vec2> hull;
  for (const Vec2& c : profile) {
    while (hull.size() >= 2) {
      const Vec2 a = hull[hull.size() - 2], b = hull.back();
      if (b.y <= a.y + (c.y - a.y) * (b.x - a.x) / (c.x - a.x)) break;
      hull.pop_back();
    }
    hull.push_back(c);
  }
  double length = 0;
  for (size_t i = 1; i < hull.size(); ++i) length += norm(hull[i] - hull[i - 1]);
  return length;
}

// bella 42 hung 60 mm above the waist of a form whose nape-to-waist was FreeSewing's
// hpsToWaistBack: the tape from the shoulder's top down the back measured 70 mm more.
TEST(FreeSewingSizes, TheFormMeasuresHpsToWaistBackDownItsBack) {
  for (int size : {28, 36, 46}) {
    SCOPED_TRACE(size);
    auto m = freesewing_cis_female_adult(size);
    ASSERT_TRUE(m);
    EXPECT_NEAR(dress_form_hps_to_waist_back_mm(*m), freesewing_hps_to_waist_back_mm(size), 1);
    auto mesh = make_dress_form(*m, DressFormOptions{.grid_spacing_mm = 6, .arms = false});
    ASSERT_TRUE(mesh) << mesh.error().what();
    auto sdf = BodySdf::build(*mesh, 4);
    ASSERT_TRUE(sdf) << sdf.error().what();
    // The mesh's facets and the neck's blend round the top: 8 mm.
    EXPECT_NEAR(tape_hps_to_waist_back_mm(*sdf, dress_form_landmarks(*m)), freesewing_hps_to_waist_back_mm(size), 8);
  }
}

// The form's sections are interpolated between landmark heights, which must rise in order:
// with the nape at hpsToWaistBack above the waist, the bust (0.44 of the back length above
// the waist) stood above the armpit (waistToArmhole above it) at every size.
TEST(FreeSewingSizes, TheBustLiesBetweenTheWaistAndTheArmpit) {
  for (int size = 28; size <= 46; size += 2) {
    SCOPED_TRACE(size);
    auto m = freesewing_cis_female_adult(size);
    ASSERT_TRUE(m);
    ASSERT_TRUE(validate(*m));
    const DressFormLandmarks l = dress_form_landmarks(*m);
    EXPECT_LT(l.waist_y, l.underbust_y);
    EXPECT_LT(l.underbust_y, l.bust_y);
    EXPECT_LT(l.bust_y + 15, l.armpit_y);
    EXPECT_LT(l.armpit_y, l.shoulder_y);
    EXPECT_LT(l.shoulder_y, l.nape_y);
  }
}

TEST(FreeSewingSizes, OnlyTheTenSizesAreKnown) {
  EXPECT_FALSE(freesewing_cis_female_adult(26));
  EXPECT_FALSE(freesewing_cis_female_adult(35));
  EXPECT_FALSE(freesewing_cis_female_adult(48));
  EXPECT_EQ(freesewing_size_in_name("teagan-cisFemaleAdult34.svg"), 34);
  EXPECT_FALSE(freesewing_size_in_name("teagan.svg"));
}

}  // namespace
}  // namespace tp::geometry
