// tests/geometry/pattern/load_pattern_test.cpp: one entry point reads every supported format.
#include "geometry/pattern/import/load_pattern.h"

#include <gtest/gtest.h>

#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

TEST(LoadPattern, DetectsEveryFormatByExtension) {
  const auto data = tp::test::shared_data_dir();
  const auto src = tp::test::source_dir();
  struct Case {
    std::filesystem::path path;
    PatternFormat format;
    size_t pieces;
  };
  for (const Case& c : {Case{src / "examples/patterns/tee.json", PatternFormat::kNative, 4},
                        Case{data / "garmentcode/patterns/shirt_mean_specification.json", PatternFormat::kGarmentCode, 8},
                        Case{data / "freesewing/teagan-cisFemaleAdult34.svg", PatternFormat::kFreeSewingSvg, 4},
                        Case{src / "examples/patterns/skirt_aama.dxf", PatternFormat::kDxfAama, 3},
                        Case{src / "tests/fuzz/corpus/geometry_obj_garment/tube2.obj", PatternFormat::kObjGarment, 2}}) {
    auto r = load_pattern(c.path);
    ASSERT_TRUE(r.has_value()) << r.error().what();
    EXPECT_EQ(r->pieces.size(), c.pieces) << c.path;
    auto f = detect_pattern_format(c.path.string(), "");
    if (c.format != PatternFormat::kNative && c.format != PatternFormat::kGarmentCode) {
      ASSERT_TRUE(f.has_value());
      EXPECT_EQ(*f, c.format) << c.path;
    }
  }
}

TEST(LoadPattern, DetectsByContentWithoutAnExtension) {
  EXPECT_EQ(*detect_pattern_format("upload", R"({"pattern": {"panels": {}}})"), PatternFormat::kGarmentCode);
  EXPECT_EQ(*detect_pattern_format("upload", "\xEF\xBB\xBF  {\"pieces\": []}"), PatternFormat::kNative);
  EXPECT_EQ(*detect_pattern_format("upload", "<?xml version=\"1.0\"?><svg/>"), PatternFormat::kFreeSewingSvg);
  EXPECT_EQ(*detect_pattern_format("upload", "  0\r\nSECTION\r\n  2\r\nHEADER\r\n"), PatternFormat::kDxfAama);
  EXPECT_EQ(*detect_pattern_format("upload", "# made by hand\nv 0 0 0\n"), PatternFormat::kObjGarment);
  auto bad = detect_pattern_format("notes.txt", "hello");
  ASSERT_FALSE(bad.has_value());
  EXPECT_NE(bad.error().message.find("notes.txt: not a pattern format"), std::string::npos);
}

TEST(LoadPattern, ErrorsComeFromTheImporterWithTheFileName) {
  auto r = read_pattern(R"({"pieces": [{"name": 3}]})", "job/pattern.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("job/pattern.json: /pieces/0/name"), std::string::npos) << r.error().message;
  auto missing = load_pattern("/nonexistent/p.dxf");
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().code, ErrorCode::kIo);
}

}  // namespace
}  // namespace tp::geometry
