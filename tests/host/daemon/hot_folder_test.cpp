// tests/host/daemon/hot_folder_test.cpp: a dropped job is taken only once it has stopped changing.
#include "host/daemon/hot_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

TEST(HotFolder, EntryIsReadyOnlyAfterSettling) {
  fs::path dir = tp::test::scratch_dir("hot-settle");
  HotFolder hot(dir, 150ms);
  ASSERT_TRUE(hot.prepare());
  EXPECT_TRUE(fs::is_directory(hot.done_dir()));
  fs::create_directories(dir / "job-a");
  std::ofstream(dir / "job-a" / "job.json") << "{}";
  EXPECT_TRUE(hot.scan().empty());  // first sight
  std::this_thread::sleep_for(200ms);
  // Still being written: the size changes, so the clock restarts.
  std::ofstream(dir / "job-a" / "pattern.json") << "{\"pieces\": []}";
  EXPECT_TRUE(hot.scan().empty());
  std::this_thread::sleep_for(200ms);
  auto ready = hot.scan();
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].filename(), "job-a");
  EXPECT_TRUE(hot.scan().empty());  // reported once
}

TEST(HotFolder, IgnoresHiddenFinishedAndNonJobEntries) {
  fs::path dir = tp::test::scratch_dir("hot-ignore");
  HotFolder hot(dir, 0ms);
  ASSERT_TRUE(hot.prepare());
  std::ofstream(dir / ".partial.zip") << "x";
  std::ofstream(dir / "notes.txt") << "x";
  std::ofstream(dir / "job.zip") << "x";
  fs::create_directories(dir / "done" / "old");
  hot.scan();
  auto ready = hot.scan();
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].filename(), "job.zip");
}

TEST(HotFolder, ZipStillOpenForWritingIsNotTakenEvenWhenItsSizeHoldsStill) {
  fs::path dir = tp::test::scratch_dir("hot-open");
  HotFolder hot(dir, 100ms);
  ASSERT_TRUE(hot.prepare());
  {
    // A copier that wrote half the file and paused, keeping it open.
    std::ofstream copier(dir / "job.zip", std::ios::binary);
    copier << "PK half";
    copier.flush();
    EXPECT_TRUE(open_for_writing(dir / "job.zip"));
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(hot.scan().empty()) << i;
      std::this_thread::sleep_for(150ms);
    }
  }
  EXPECT_FALSE(open_for_writing(dir / "job.zip"));
  // Closed: taken after one more settle time.
  std::vector<fs::path> ready;
  for (int i = 0; i < 5 && ready.empty(); ++i) {
    ready = hot.scan();
    std::this_thread::sleep_for(150ms);
  }
  ASSERT_EQ(ready.size(), 1u);
}

}  // namespace
}  // namespace tp::host
