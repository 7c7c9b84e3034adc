// tests/host/pipeline/printed_fabric_wait_test.cpp: the wait for printsim's fabric images wakes
// when the files are written (not after a polling interval), finds --job-dirs folders made during
// the wait, ignores an earlier run's printer.json for the same job id, and fails naming the folder
// and job when nothing comes.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "host/pipeline/internal/printed_fabric_wait.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using host::internal::PrintedFabricWait;
using host::internal::wait_for_printed_fabric;
using Clock = std::chrono::steady_clock;

// What printsim writes at a job's end: the fabric image (unless --no-fabric), then printer.json.
void write_record(const fs::path& dir, std::int64_t job_id, bool fabric) {
  fs::create_directories(dir);
  if (fabric) std::ofstream(dir / "fabric-lab.tif") << "lab";
  std::ofstream(dir / "printer.json") << "{\"job\": {\"id\": " << job_id << ", \"name\": \"j\"}}\n";
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

TEST(PrintedFabricWait, WakesWhenPrintsimWritesAJobFolder) {
  const fs::path dir = scratch_dir("fabric_wait_wakes");
  // Another job's folder is there already; this job's appears while waiting (printsim --job-dirs).
  write_record(dir / "6-other", 6, true);
  std::thread printsim([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    write_record(dir / "7-shirt", 7, true);
  });
  const auto start = Clock::now();
  auto found = wait_for_printed_fabric({dir, 7, std::nullopt, 30}, geometry::CancelToken{});
  const double waited_s = seconds_since(start);
  printsim.join();
  ASSERT_TRUE(found) << found.error().message;
  ASSERT_TRUE(found->fabric_lab);
  EXPECT_EQ(*found->fabric_lab, dir / "7-shirt" / "fabric-lab.tif");
  // Woken by the write, well before the one-second fallback look would have seen it.
  EXPECT_LT(waited_s, 0.9);
}

TEST(PrintedFabricWait, APrintWithoutFabricGivesAReasonAtOnce) {
  const fs::path dir = scratch_dir("fabric_wait_nofabric");
  write_record(dir, 3, false);
  auto found = wait_for_printed_fabric({dir, 3, std::nullopt, 30}, geometry::CancelToken{});
  ASSERT_TRUE(found) << found.error().message;
  EXPECT_FALSE(found->fabric_lab);
  EXPECT_NE(found->reason.find("without a fabric-lab.tif"), std::string::npos) << found->reason;
}

TEST(PrintedFabricWait, AnEarlierRunsRecordIsNotThisJobs) {
  const fs::path dir = scratch_dir("fabric_wait_stale");
  // A fresh printd numbers its jobs from 1 again: job 1 of an earlier run left its record here.
  write_record(dir, 1, true);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const auto began = fs::file_time_type::clock::now();
  auto stale = wait_for_printed_fabric({dir, 1, began, 0.3}, geometry::CancelToken{});
  ASSERT_FALSE(stale);
  EXPECT_EQ(stale.error().code, host::ErrorCode::kPrinter);
  EXPECT_NE(stale.error().message.find("job 1"), std::string::npos) << stale.error().message;
  EXPECT_NE(stale.error().message.find(dir.string()), std::string::npos) << stale.error().message;
  EXPECT_NE(stale.error().message.find("within 0.3 s"), std::string::npos) << stale.error().message;

  // This run's record, written after the print began, is taken.
  std::thread printsim([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    write_record(dir, 1, true);
  });
  auto found = wait_for_printed_fabric({dir, 1, began, 30}, geometry::CancelToken{});
  printsim.join();
  ASSERT_TRUE(found) << found.error().message;
  EXPECT_TRUE(found->fabric_lab);
}

TEST(PrintedFabricWait, TimesOutAndCancelsWithClearErrors) {
  const fs::path dir = scratch_dir("fabric_wait_timeout");
  fs::create_directories(dir);
  const auto start = Clock::now();
  auto none = wait_for_printed_fabric({dir, 9, std::nullopt, 1.5}, geometry::CancelToken{});
  EXPECT_GE(seconds_since(start), 1.4);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().code, host::ErrorCode::kPrinter);
  EXPECT_NE(none.error().message.find("no printer.json for job 9"), std::string::npos) << none.error().message;

  geometry::CancelToken cancel;
  cancel.cancel();
  auto cancelled = wait_for_printed_fabric({dir, 9, std::nullopt, 30}, cancel);
  ASSERT_FALSE(cancelled);
  EXPECT_EQ(cancelled.error().code, host::ErrorCode::kCancelled);

  auto missing = wait_for_printed_fabric({dir / "absent", 9, std::nullopt, 30}, geometry::CancelToken{});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, host::ErrorCode::kIo);
}

}  // namespace
}  // namespace tp::test
