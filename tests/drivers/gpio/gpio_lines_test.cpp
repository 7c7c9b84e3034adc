// tests/drivers/gpio/gpio_lines_test.cpp: libgpiod through printsim's emulated chip: named lines,
// output edges logged by the virtual cutting table, input levels, busy and missing lines.
#include "drivers/gpio/gpio_lines.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/drivers/under_printsim.h"

namespace tp::drivers {
namespace {

TEST(GpioLines, DrivesOutputsAndReadsInputsByName) {
  std::filesystem::path out;
  if (!test::rerun_under_printsim({}, &out)) {
    std::ifstream in(out / "printsim.json");
    auto j = nlohmann::json::parse(in);
    std::vector<std::pair<std::string, int>> edges;
    for (const auto& e : j["gpio_edges"]) edges.emplace_back(e["line"], e["level"]);
    const std::vector<std::pair<std::string, int>> want = {
        {"cutter-cue", 1}, {"cutter-cue", 0}, {"notch-mark", 1}, {"notch-mark", 0}};
    EXPECT_EQ(edges, want);
    return;
  }
  auto lines = GpioLines::open({});
  ASSERT_TRUE(lines) << lines.error().message;
  ASSERT_TRUE((*lines)->pulse(GpioOutput::kCutterCue, std::chrono::microseconds(500)));
  ASSERT_TRUE((*lines)->pulse(GpioOutput::kNotchMark, std::chrono::microseconds(500)));
  auto ready = (*lines)->cutter_ready();
  ASSERT_TRUE(ready);
  EXPECT_TRUE(*ready);
  auto estop = (*lines)->emergency_stop();
  ASSERT_TRUE(estop);
  EXPECT_FALSE(*estop);
}

TEST(GpioLines, HonoursActiveLowInputs) {
  if (!test::rerun_under_printsim()) return;
  GpioConfig c;
  c.cutter_ready_active_low = true;
  auto lines = GpioLines::open(c);
  ASSERT_TRUE(lines) << lines.error().message;
  auto ready = (*lines)->cutter_ready();
  ASSERT_TRUE(ready);
  EXPECT_FALSE(*ready) << "the line is high, so an active-low 'ready' reads not ready";
}

TEST(GpioLines, NamesAMissingLineAndABusyOne) {
  if (!test::rerun_under_printsim()) return;
  GpioConfig bad;
  bad.cutter_cue = "knife";
  auto missing = GpioLines::open(bad);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
  EXPECT_NE(missing.error().message.find("no line named 'knife'"), std::string::npos) << missing.error().message;

  auto first = GpioLines::open({});
  ASSERT_TRUE(first) << first.error().message;
  auto second = GpioLines::open({});
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().code, ErrorCode::kBusy) << second.error().message;
  first->reset();
  auto third = GpioLines::open({});
  EXPECT_TRUE(third) << "closing the first set released its lines";
}

TEST(GpioLines, NamesAMissingChip) {
  if (!test::rerun_under_printsim()) return;
  GpioConfig c;
  c.chip = "gpiochip9";
  auto lines = GpioLines::open(c);
  ASSERT_FALSE(lines);
  EXPECT_NE(lines.error().message.find("gpiochip9"), std::string::npos);
}

}  // namespace
}  // namespace tp::drivers
