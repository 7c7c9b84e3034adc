// tests/drivers/usb/ieee1284_id_test.cpp: parsing and matching IEEE 1284 device IDs.
#include "drivers/usb/ieee1284_id.h"

#include <gtest/gtest.h>

namespace tp::drivers {
namespace {

TEST(Ieee1284Id, ParsesLongAndShortKeys) {
  auto f = parse_ieee1284_id("MANUFACTURER:Acme;MODEL:TP 9;COMMAND SET:PCL,TPWP;CLS:PRINTER;junk;");
  EXPECT_EQ(f["MFG"], "Acme");
  EXPECT_EQ(f["MDL"], "TP 9");
  EXPECT_EQ(f["CMD"], "PCL,TPWP");
  EXPECT_EQ(f.size(), 4u);
}

TEST(Ieee1284Id, MatchesEveryPatternField) {
  const char* id = "MFG:TextilePrint;MDL:TP-SIM-1600;CMD:PJL, TPWP;CLS:PRINTER;";
  EXPECT_TRUE(ieee1284_matches(id, ""));
  EXPECT_TRUE(ieee1284_matches(id, "CMD:TPWP;"));
  EXPECT_TRUE(ieee1284_matches(id, "CMD:PJL;MDL:TP-SIM-1600;"));
  EXPECT_FALSE(ieee1284_matches(id, "CMD:PCL;"));
  EXPECT_FALSE(ieee1284_matches(id, "MDL:TP-SIM-1601;"));
  EXPECT_FALSE(ieee1284_matches(id, "SN:1;"));
  EXPECT_FALSE(ieee1284_matches("", "CMD:TPWP;"));
}

}  // namespace
}  // namespace tp::drivers
