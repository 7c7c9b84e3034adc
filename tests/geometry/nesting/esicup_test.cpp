// tests/geometry/nesting/esicup_test.cpp: the ESICUP instance reader on the reference files and on
// broken input, whose errors must name the file and the field.
#include "geometry/nesting/esicup.h"

#include <gtest/gtest.h>

#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

TEST(Esicup, ReadsTheReferenceInstances) {
  struct Expect {
    const char* name;
    double width;
    size_t types;
    int copies;
  };
  for (const Expect& e : {Expect{"shirts", 40, 8, 99}, Expect{"trousers", 79, 17, 64}, Expect{"swim", 5752, 10, 48},
                          Expect{"albano", 4900, 8, 24}, Expect{"dagli", 60, 10, 30}, Expect{"jakobs1", 40.004, 25, 25}}) {
    SCOPED_TRACE(e.name);
    auto p = load_esicup(test::shared_data_dir() / "esicup" / (std::string(e.name) + ".json"));
    ASSERT_TRUE(p) << p.error().what();
    EXPECT_EQ(p->name, e.name);
    EXPECT_DOUBLE_EQ(p->width, e.width);
    EXPECT_EQ(p->items.size(), e.types);
    int copies = 0;
    for (const StripItem& it : p->items) {
      copies += it.demand;
      EXPECT_GE(it.shape.size(), 3u);
      EXPECT_NE(it.shape.front(), it.shape.back()) << "the closing repeat of the first point is dropped";
    }
    EXPECT_EQ(copies, e.copies);
  }
}

TEST(Esicup, KeepsOrientationsAndShapeTypes) {
  const char* text = R"({"name": "t", "strip_height": 10, "items": [
      {"id": 3, "demand": 2, "allowed_orientations": [0, 90.0, 270],
       "shape": {"type": "simple_polygon", "data": [[0,0],[2,0],[2,1],[0,1],[0,0]]}},
      {"id": 4, "demand": 1, "shape": {"type": "rectangle", "data": {"x_min": 1, "y_min": 2, "width": 3, "height": 4}}},
      {"id": 5, "demand": 1, "shape": {"type": "polygon", "data": {"outer": [[0,0],[5,0],[0,5]], "inner": []}}}]})";
  auto p = parse_esicup(text, "t.json");
  ASSERT_TRUE(p) << p.error().what();
  ASSERT_EQ(p->items.size(), 3u);
  EXPECT_EQ(p->items[0].id, 3);
  ASSERT_EQ(p->items[0].poses.size(), 3u);
  EXPECT_EQ(p->items[0].poses[1].rotation_deg, 90.0);
  EXPECT_EQ(p->items[0].shape.size(), 4u);
  ASSERT_EQ(p->items[1].poses.size(), 1u) << "no allowed_orientations: as given only";
  EXPECT_EQ(p->items[1].shape[2], (Vec2{4, 6}));
  EXPECT_EQ(p->items[2].shape.size(), 3u);
}

struct Broken {
  const char* json;
  const char* expect;  // substring of the error message
};

TEST(Esicup, BrokenInputNamesFileAndField) {
  const Broken cases[] = {
      {"{", "not valid JSON"},
      {"[]", "bad.json: /: expected an object"},
      {R"({"items": []})", "/strip_height: missing"},
      {R"({"strip_height": "wide", "items": []})", "/strip_height: expected a number"},
      {R"({"strip_height": -4, "items": []})", "/strip_height: must be greater than 0"},
      {R"({"strip_height": 4})", "/items: expected an array"},
      {R"({"strip_height": 4, "items": []})", "/items: no items"},
      {R"({"strip_height": 4, "items": [{"demand": 1}]})", "/items/0/id: expected an integer"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": -1}]})", "/items/0/demand: out of range"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1.5}]})", "/items/0/demand: expected an integer"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1}]})", "/items/0/shape: missing"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "shape": {"type": "circle", "data": 1}}]})",
       "/items/0/shape/type: unsupported shape type 'circle'"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "shape": {"type": "simple_polygon",
          "data": [[0,0],[1,0],[1]]}}]})",
       "/items/0/shape/data/2: expected a point [x, y]"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "shape": {"type": "simple_polygon",
          "data": [[0,0],[1,"a"],[1,1]]}}]})",
       "/items/0/shape/data/1/1: expected a number"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "shape": {"type": "simple_polygon",
          "data": [[0,0],[1,0],[0,0]]}}]})",
       "/items/0/shape/data: a polygon needs at least 3 distinct points"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "allowed_orientations": [],
          "shape": {"type": "simple_polygon", "data": [[0,0],[1,0],[1,1]]}}]})",
       "/items/0/allowed_orientations: expected a non-empty array"},
      {R"({"strip_height": 4, "items": [{"id": 0, "demand": 1, "shape": {"type": "rectangle",
          "data": {"x_min": 0, "y_min": 0, "width": 0, "height": 1}}}]})",
       "/items/0/shape/data/width: must be greater than 0"},
      {R"({"strip_height": 1e400, "items": []})", "not valid JSON"},
  };
  for (const Broken& c : cases) {
    SCOPED_TRACE(c.json);
    auto p = parse_esicup(c.json, "bad.json");
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().code, ErrorCode::kParse);
    EXPECT_NE(p.error().message.find("bad.json"), std::string::npos) << p.error().message;
    EXPECT_NE(p.error().message.find(c.expect), std::string::npos) << p.error().message;
  }
}

TEST(Esicup, MissingFileIsAnIoError) {
  auto p = load_esicup(test::scratch_dir("esicup_missing") / "none.json");
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error().code, ErrorCode::kIo);
  EXPECT_NE(p.error().message.find("none.json"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
