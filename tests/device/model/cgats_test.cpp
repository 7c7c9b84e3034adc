// tests/device/model/cgats_test.cpp: CGATS tables read back what was written, Argyll-style files
// parse, and broken files fail naming file and line.
#include "device/model/cgats.h"

#include <gtest/gtest.h>

namespace tp::device {
namespace {

constexpr const char* kArgyllTi3 = R"(CTI3

DESCRIPTOR "Argyll Calibration Target chart information 3"
ORIGINATOR "Argyll target"
CREATED "Wed Dec  2 00:00:00 2026"
KEYWORD "DEVICE_CLASS"
DEVICE_CLASS "OUTPUT"
KEYWORD "COLOR_REP"
COLOR_REP "CMYK_XYZ"

NUMBER_OF_FIELDS 8
BEGIN_DATA_FORMAT
SAMPLE_ID CMYK_C CMYK_M CMYK_Y CMYK_K XYZ_X XYZ_Y XYZ_Z
END_DATA_FORMAT

NUMBER_OF_SETS 2
BEGIN_DATA
1 0.00 0.00 0.00 0.00 85.1 88.2 70.3
2 100.00 0.00 0.00 0.00 14.2 20.1 45.0
END_DATA
)";

TEST(Cgats, ParsesArgyllFilesAndRoundTrips) {
  auto t = parse_cgats(kArgyllTi3, "m.ti3");
  ASSERT_TRUE(t) << t.error().message;
  ASSERT_EQ(t->size(), 1u);
  const CgatsTable& m = t->front();
  EXPECT_EQ(m.type, "CTI3");
  EXPECT_EQ(m.keyword("COLOR_REP"), "CMYK_XYZ");
  EXPECT_EQ(m.keyword("CREATED"), "Wed Dec  2 00:00:00 2026");
  EXPECT_EQ(m.field("XYZ_Y"), 6);
  ASSERT_EQ(m.rows.size(), 2u);
  EXPECT_EQ(m.rows[1][1], "100.00");
  auto again = parse_cgats(format_cgats(m), "again");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(again->front().rows, m.rows);
  EXPECT_EQ(again->front().fields, m.fields);
  EXPECT_EQ(again->front().keyword("DEVICE_CLASS"), "OUTPUT");
}

TEST(Cgats, BrokenFilesNameFileAndLine) {
  struct Case {
    std::string text, expect;
  };
  const Case cases[] = {
      {"", "m.ti3: no CGATS table"},
      {"CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID XYZ_X\nEND_DATA_FORMAT\nBEGIN_DATA\n1 2\n3\nEND_DATA\n", "m.ti3:7: data row has 1 values"},
      {"CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID XYZ_X\nEND_DATA_FORMAT\nNUMBER_OF_SETS 3\nBEGIN_DATA\n1 2\nEND_DATA\n",
       "m.ti3:8: NUMBER_OF_SETS says 3 but the table has 1 rows"},
      {"CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID XYZ_X\nEND_DATA_FORMAT\nBEGIN_DATA\n1 2\n", "m.ti3: BEGIN_DATA without END_DATA"},
      {"CTI3\nDESCRIPTOR \"open\n", "m.ti3:2: unterminated quoted string"},
      {"CTI3\nBEGIN_DATA\n", "m.ti3:2: BEGIN_DATA before any BEGIN_DATA_FORMAT"},
      {"not a cgats file at all\n", "m.ti3:1: expected a CGATS file identifier"},
  };
  for (const auto& c : cases) {
    auto r = parse_cgats(c.text, "m.ti3");
    ASSERT_FALSE(r) << c.text;
    EXPECT_NE(r.error().message.find(c.expect), std::string::npos) << r.error().message;
  }
}

}  // namespace
}  // namespace tp::device
