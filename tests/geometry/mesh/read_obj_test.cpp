// tests/geometry/mesh/read_obj_test.cpp: the one OBJ reader: corner forms, fans, groups, errors with file and line.
#include "geometry/mesh/read_obj.h"

#include <gtest/gtest.h>

#include <string>

namespace tp::geometry {
namespace {

std::string message_of(std::string_view text, ObjReadOptions options = {}) {
  auto m = read_obj(text, "m.obj", options);
  return m ? std::string("accepted") : m.error().message;
}

TEST(ReadObj, ReadsEveryCornerFormAndFansPolygons) {
  const char* text =
      "# quad and triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
      "g front\nf 1/1/1 2/2/1 3/3/1 4/3/1\no back\nf 1//1 3//1 4//1\ng front\nf -4 -2 -1\n";
  auto m = read_obj(text, "m.obj");
  ASSERT_TRUE(m) << m.error().what();
  ASSERT_EQ(m->positions.size(), 4u);
  ASSERT_EQ(m->uvs.size(), 3u);
  ASSERT_EQ(m->triangles.size(), 4u);
  ASSERT_EQ(m->groups, (std::vector<std::string>{"front", "back"}));
  // The quad is fanned from its first corner; its corners keep their texture indices.
  EXPECT_EQ(m->triangles[1].c[1].v, 2);
  EXPECT_EQ(m->triangles[1].c[2].v, 3);
  EXPECT_EQ(m->triangles[1].c[2].vt, 2);
  EXPECT_EQ(m->triangles[0].line, 11);
  EXPECT_EQ(m->triangles[0].group, 0);
  // v//vn and plain v corners have no texture coordinate; negative indices count back.
  EXPECT_EQ(m->triangles[2].c[0].vt, -1);
  EXPECT_EQ(m->triangles[2].group, 1);
  EXPECT_EQ(m->triangles[3].c[0].v, 0);
  EXPECT_EQ(m->triangles[3].c[2].v, 3);
  EXPECT_EQ(m->triangles[3].group, 0);
  EXPECT_EQ(m->uvs[2].x, 1);
}

TEST(ReadObj, FacesWithoutTexturesFailOnlyWhenTexturesAreRequired) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n";
  EXPECT_EQ(message_of(tri), "accepted");
  EXPECT_NE(message_of(tri, {.require_texture_coordinates = true}).find("m.obj:5: face corner '1' has no texture"),
            std::string::npos);
  EXPECT_EQ(message_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n", {.require_texture_coordinates = true}),
            "accepted");
}

TEST(ReadObj, ErrorsNameTheFileAndLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
  EXPECT_NE(message_of("v 0 0 0\nv 1 0\n").find("m.obj:2: v needs 3 numbers"), std::string::npos);
  EXPECT_NE(message_of("vt 0 nan\n").find("m.obj:1: vt needs 2 numbers"), std::string::npos);
  EXPECT_NE(message_of(tri + "f 1 2 7\n").find("m.obj:5: vertex index 7 out of range (1..3)"), std::string::npos);
  EXPECT_NE(message_of(tri + "f 1/1 2/2 3/1\n").find("m.obj:5: texture index 2 out of range (1..1)"),
            std::string::npos);
  EXPECT_NE(message_of(tri + "f 1 0 2\n").find("m.obj:5: bad face corner '0'"), std::string::npos);
  EXPECT_NE(message_of(tri + "f 1 2x 3\n").find("bad face corner '2x'"), std::string::npos);
  EXPECT_NE(message_of(tri + "f 1 2\n").find("m.obj:5: a face needs at least 3 corners"), std::string::npos);
  // Indices count only what came before the face.
  EXPECT_NE(message_of("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n").find("m.obj:2: vertex index 2"), std::string::npos);
}

TEST(ReadObj, AFileWithoutFacesIsLeftToTheCaller) {
  auto m = read_obj("# nothing\nv 1 2 3\nusemtl skin\ns off\n", "m.obj");
  ASSERT_TRUE(m) << m.error().what();
  EXPECT_EQ(m->positions.size(), 1u);
  EXPECT_TRUE(m->triangles.empty());
}

}  // namespace
}  // namespace tp::geometry
