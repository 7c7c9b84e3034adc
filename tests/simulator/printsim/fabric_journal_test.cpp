// tests/simulator/printsim/fabric_journal_test.cpp: printed swaths survive in the journal and
// replay in order up to the resume point; later records and a torn tail are cut off.
#include "simulator/printsim/fabric_journal.h"

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

#include "tests/support/paths.h"

namespace tp::sim {
namespace {

device::SwathHeader header(std::uint32_t index) {
  device::SwathHeader h;
  h.index = index;
  h.rows = 4;
  h.first_row = index * 4;
  h.width_px = 16;
  h.channels = 4;
  h.bits_per_pixel = 2;
  h.raw_bytes = static_cast<std::uint32_t>(device::swath_raw_bytes(h));
  return h;
}

std::vector<std::uint8_t> raw(std::uint32_t index) {
  std::vector<std::uint8_t> r(header(index).raw_bytes);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = static_cast<std::uint8_t>((i * 7 + index) % 5 == 0 ? 0x55 : 0);
  return r;
}

TEST(FabricJournal, ReplaysThePrintedSwathsBeforeTheResumePoint) {
  const auto path = test::scratch_dir("fabric-journal") / "j";
  {
    auto j = FabricJournal::create(path, 7);
    ASSERT_TRUE(j);
    for (std::uint32_t i = 0; i < 4; ++i) ASSERT_TRUE(j->append(header(i), raw(i)));
  }
  std::ofstream(path, std::ios::app) << "torn";  // a record cut short by the power loss
  std::vector<std::uint32_t> seen;
  auto j = FabricJournal::reopen(path, 7, 3, [&](const device::SwathHeader& h, std::span<const std::uint8_t> data) {
    seen.push_back(h.index);
    EXPECT_EQ(std::vector<std::uint8_t>(data.begin(), data.end()), raw(h.index));
  });
  ASSERT_TRUE(j) << j.error().what();
  EXPECT_EQ(seen, (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_TRUE(j->append(header(3), raw(3)));
  j->discard();
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(FabricJournal, RefusesAnotherJobsJournal) {
  const auto path = test::scratch_dir("fabric-journal-other") / "j";
  ASSERT_TRUE(FabricJournal::create(path, 7));
  auto j = FabricJournal::reopen(path, 8, 1, [](const device::SwathHeader&, std::span<const std::uint8_t>) {});
  ASSERT_FALSE(j);
  EXPECT_NE(j.error().what().find("job 7"), std::string::npos) << j.error().what();
}

}  // namespace
}  // namespace tp::sim
