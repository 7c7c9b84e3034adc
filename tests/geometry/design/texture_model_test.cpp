// tests/geometry/design/texture_model_test.cpp: the textured OBJ of a texture-transfer layer:
// units, faces to triangles with their UVs, the model printing on the pieces, and broken files.
#include <gtest/gtest.h>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/texture_model.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

// A quad 1 mm in front of the test garment's front panel, in cm, its UVs the unit square.
constexpr const char* kQuadCm =
    "# painted in another tool\n"
    "mtllib painted.mtl\n"
    "o painted\n"
    "v -10 0 2.1\nv 10 0 2.1\nv 10 30 2.1\nv -10 30 2.1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n"
    "usemtl paint\n"
    "f 1/1/1 2/2/1 3/3/1 4/4/1\n";

TEST(TextureModel, ReadsAQuadInCentimetresAsTwoTrianglesInMillimetres) {
  auto t = read_texture_model(kQuadCm, "painted.obj", 10.0);
  ASSERT_TRUE(t) << t.error().what();
  ASSERT_EQ(t->vertices_mm.size(), 4u);
  EXPECT_DOUBLE_EQ(t->vertices_mm[2].x, 100);
  EXPECT_DOUBLE_EQ(t->vertices_mm[2].y, 300);
  EXPECT_DOUBLE_EQ(t->vertices_mm[2].z, 21);
  ASSERT_EQ(t->triangles.size(), 2u);  // the quad, fan-triangulated
  EXPECT_EQ(t->triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(t->uv_triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(t->uvs[2].x, 1);
}

TEST(TextureModel, TheLoadedModelPrintsItsImageOnThePieces) {
  auto g = test::flat_panels(200, 300);
  auto t = read_texture_model(kQuadCm, "painted.obj", 10.0);
  ASSERT_TRUE(t);
  t->image = test::make_image(64, 96, [](int x, int) { return x < 32 ? Rgba8{250, 0, 0, 255} : Rgba8{0, 0, 250, 255}; });
  Design d;
  d.layers.push_back({"painted", 1.0, *t});
  Finishing f;
  f.marks = MarkMode::kNone;
  auto r = make_piece_renderer(g.pattern, g.garment, d, f);
  ASSERT_TRUE(r) << r.error().what();
  auto at = [&](Vec2 p) {
    const double s = 25.4 / 300;
    Rgba8 px{};
    (*r)->render(0, Affine2{s, 0, p.x - 0.5 * s, 0, -s, p.y + 0.5 * s}, 1, 1, &px, 1);
    return px;
  };
  EXPECT_EQ(at({50, 150}), (Rgba8{250, 0, 0, 255}));
  EXPECT_EQ(at({150, 150}), (Rgba8{0, 0, 250, 255}));
}

TEST(TextureModel, BrokenFilesAreRefusedNamingFileAndLine) {
  auto bad_number = read_texture_model("v 0 0 0\nv 1 x 0\n", "paint.obj");
  ASSERT_FALSE(bad_number);
  EXPECT_NE(bad_number.error().message.find("paint.obj:2"), std::string::npos) << bad_number.error().message;

  auto no_uvs = read_texture_model("v 0 0 0\nv 100 0 0\nv 0 100 0\nf 1 2 3\n", "paint.obj");
  ASSERT_FALSE(no_uvs);
  EXPECT_NE(no_uvs.error().message.find("paint.obj:4"), std::string::npos) << no_uvs.error().message;

  auto no_faces = read_texture_model("v 0 0 0\nvt 0 0\n", "paint.obj");
  ASSERT_FALSE(no_faces);
  EXPECT_NE(no_faces.error().message.find("no faces"), std::string::npos);

  auto out_of_range = read_texture_model("v 0 0 0\nv 100 0 0\nv 0 100 0\nvt 0 0\nf 1/1 2/1 9/1\n", "paint.obj");
  ASSERT_FALSE(out_of_range);
  EXPECT_NE(out_of_range.error().message.find("paint.obj:5"), std::string::npos) << out_of_range.error().message;

  // Metres read as millimetres: a garment a millimetre across means wrong units.
  auto tiny = read_texture_model("v 0 0 0\nv 0.5 0 0\nv 0 0.5 0\nvt 0 0\nf 1/1 2/1 3/1\n", "paint.obj");
  ASSERT_FALSE(tiny);
  EXPECT_NE(tiny.error().message.find("units"), std::string::npos);

  auto missing = load_texture_model("/nonexistent/paint.obj");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("/nonexistent/paint.obj"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
