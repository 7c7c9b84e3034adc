// tests/host/daemon/events/event_log_test.cpp: sequence numbers are dense and increasing, a reader
// resumes after any number it saw, and one that fell out of the bounded log is told of the gap.
#include "host/daemon/events/event_log.h"

#include <gtest/gtest.h>

#include <thread>

namespace tp::host {
namespace {

using namespace std::chrono_literals;

TEST(EventLog, ReplaysEverythingAfterTheLastSeenNumber) {
  EventLog log(100, 1000);
  for (int i = 0; i < 10; ++i) log.publish("progress", 7, {{"i", i}});
  EXPECT_EQ(log.last_seq(), 1009u);
  auto b = log.read_after(1004, 100, 0ms);
  ASSERT_EQ(b.events.size(), 5u);
  EXPECT_FALSE(b.gap);
  for (size_t k = 0; k < b.events.size(); ++k) {
    EXPECT_EQ(b.events[k].seq, 1005 + k);
    EXPECT_EQ(b.events[k].data["i"], static_cast<int>(5 + k));
    EXPECT_EQ(b.events[k].job_id, 7);
  }
  EXPECT_TRUE(log.read_after(1009, 100, 0ms).events.empty());
}

TEST(EventLog, AReaderBehindTheBoundIsToldOfTheGap) {
  EventLog log(4, 1);
  for (int i = 0; i < 10; ++i) log.publish("job", 1, {});
  auto b = log.read_after(2, 100, 0ms);
  EXPECT_TRUE(b.gap);
  EXPECT_EQ(b.first_kept, 7u);
  ASSERT_EQ(b.events.size(), 4u);
  EXPECT_EQ(b.events.front().seq, 7u);
  // A number from another run (beyond the newest) reads as "from the start".
  auto f = log.read_after(999, 100, 0ms);
  EXPECT_TRUE(f.gap);
  EXPECT_EQ(f.events.size(), 4u);
}

TEST(EventLog, AWaitingReaderWakesOnPublish) {
  EventLog log(16, 1);
  std::thread t([&] {
    std::this_thread::sleep_for(50ms);
    log.publish("printer", 0, {{"state", "idle"}});
  });
  auto b = log.read_after(0, 10, 5000ms);
  t.join();
  ASSERT_EQ(b.events.size(), 1u);
  EXPECT_EQ(b.events[0].type, "printer");
}

TEST(EventLog, SseFrameCarriesIdTypeAndJson) {
  DaemonEvent e{42, "progress", 3, 1000, {{"stage", "print"}, {"fraction", 0.5}}};
  const std::string f = to_sse(e);
  EXPECT_EQ(f.rfind("id: 42\nevent: progress\ndata: {", 0), 0u) << f;
  EXPECT_NE(f.find("\"job_id\":3"), std::string::npos);
  EXPECT_NE(f.find("\"fraction\":0.5"), std::string::npos);
  EXPECT_EQ(f.substr(f.size() - 2), "\n\n");
}

}  // namespace
}  // namespace tp::host
