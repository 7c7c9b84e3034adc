// tests/simulator/scenario/scenario_test.cpp: scenario files parse, and mistakes are reported with
// the file and the JSON pointer of the field.
#include "simulator/scenario/scenario.h"

#include <gtest/gtest.h>

namespace tp::sim {
namespace {

TEST(Scenario, ParsesEveryFaultKindAndTrigger) {
  auto s = parse_scenario(R"({
    "description": "all of them",
    "faults": [
      {"type": "stall", "at_swath": 3},
      {"type": "drop_frame", "at_frame": 40, "count": 2},
      {"type": "corrupt_crc", "at_frame": 50},
      {"type": "unplug", "at_swath": 5, "duration_ms": 400},
      {"type": "ink_low", "after_ms": 100, "duration_ms": 900},
      {"type": "media_jam", "at_swath": 9},
      {"type": "cutter_not_ready", "at_swath": 2, "duration_ms": 700},
      {"type": "emergency_stop", "at_swath": 7},
      {"type": "power_loss", "at_swath": 4, "duration_ms": 300},
      {"type": "buffer_clear", "at_swath": 6}
    ],
    "expect": {"outcome": "identical"}
  })", "all.json");
  ASSERT_TRUE(s) << s.error().message;
  ASSERT_EQ(s->faults.size(), 10u);
  EXPECT_EQ(s->faults[8].type, FaultType::kPowerLoss);
  EXPECT_EQ(s->faults[9].type, FaultType::kBufferClear);
  EXPECT_EQ(s->faults[1].type, FaultType::kDropFrame);
  EXPECT_EQ(s->faults[1].count, 2u);
  EXPECT_EQ(*s->faults[3].at_swath, 5u);
  EXPECT_EQ(s->faults[3].duration_ms, 400);
  EXPECT_EQ(*s->faults[4].after_ms, 100);
  EXPECT_EQ(s->description, "all of them");
}

TEST(Scenario, ErrorsNameTheFileAndThePointer) {
  struct Case {
    const char* json;
    const char* expect;
  } cases[] = {
      {"[1]", "jam.json: /: expected an object"},
      {R"({"faults": [{"type": "jammed", "at_swath": 1}]})", "jam.json: /faults/0/type: unknown fault 'jammed'"},
      {R"({"faults": [{"type": "stall"}]})", "/faults/0: needs exactly one of at_swath, at_frame, after_ms"},
      {R"({"faults": [{"type": "stall", "at_swath": 1, "after_ms": 3}]})", "needs exactly one"},
      {R"({"faults": [{"type": "drop_frame", "at_swath": 1}]})", "drop_frame needs at_frame"},
      {R"({"faults": [{"type": "unplug", "at_swath": 1}]})", "/faults/0/duration_ms: missing or zero"},
      {R"({"faults": [{"type": "stall", "at_swath": -1}]})", "/faults/0/at_swath: expected a non-negative integer"},
      {R"({"faults": [{"type": "stall", "at_swath": 1, "when": 2}]})", "/faults/0/when: unknown key"},
      {R"({"fault": []})", "/fault: unknown key"},
      {R"({"faults": [{"type": "corrupt_crc", "at_frame": 0}]})", "frames are numbered from 1"},
      {"{not json", "jam.json: not valid JSON"},
      {R"({"faults": [{"type": "stall", "at_swath": 1e999}]})", "jam.json: not valid JSON"},
  };
  for (const auto& c : cases) {
    auto s = parse_scenario(c.json, "jam.json");
    ASSERT_FALSE(s) << c.json;
    EXPECT_EQ(s.error().code, ErrorCode::kScenario);
    EXPECT_NE(s.error().message.find(c.expect), std::string::npos) << "got: " << s.error().message;
  }
}

TEST(Scenario, MissingFileIsNamed) {
  auto s = load_scenario("/no/such/scenario.json");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("/no/such/scenario.json"), std::string::npos);
}

}  // namespace
}  // namespace tp::sim
