// tests/host/store/job_store_test.cpp: the job queue survives reopening and claims jobs once.
#include "host/store/job_store.h"

#include <gtest/gtest.h>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

TEST(JobStore, QueueSurvivesReopen) {
  auto dir = tp::test::scratch_dir("store-reopen");
  {
    auto store = JobStore::open(dir / "jobs.db");
    ASSERT_TRUE(store) << store.error().message;
    ASSERT_TRUE(store->enqueue("a", "/spool/1", "/out/a", "cli"));
    ASSERT_TRUE(store->enqueue("b", "/spool/2", "/out/b", "cli"));
  }
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto first = store->claim_next();
  ASSERT_TRUE(first && *first);
  EXPECT_EQ((*first)->name, "a");
  EXPECT_EQ((*first)->state, JobState::kRunning);
  auto second = store->claim_next();
  ASSERT_TRUE(second && *second);
  EXPECT_EQ((*second)->name, "b");
  auto none = store->claim_next();
  ASSERT_TRUE(none);
  EXPECT_FALSE(*none);
}

TEST(JobStore, InterruptedJobIsRequeuedWithItsCheckpoint) {
  auto dir = tp::test::scratch_dir("store-requeue");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto id = store->enqueue("a", "/spool/1", "/out/a", "cli");
  ASSERT_TRUE(id);
  ASSERT_TRUE(store->claim_next());
  ASSERT_TRUE(store->set_checkpoint(*id, 41));
  auto n = store->requeue_interrupted();
  ASSERT_TRUE(n);
  EXPECT_EQ(n->requeued, 1);
  EXPECT_EQ(n->failed, 0);
  auto rec = store->get(*id);
  ASSERT_TRUE(rec && *rec);
  EXPECT_EQ((*rec)->state, JobState::kQueued);
  EXPECT_EQ((*rec)->last_acked_swath, 41);
}

TEST(JobStore, CancelQueuedAndRunningJobs) {
  auto dir = tp::test::scratch_dir("store-cancel");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto a = store->enqueue("a", "p", "o", "cli");
  auto b = store->enqueue("b", "p", "o", "cli");
  ASSERT_TRUE(a && b);
  ASSERT_TRUE(store->claim_next());  // a is running
  auto ca = store->request_cancel(*a);
  ASSERT_TRUE(ca);
  EXPECT_EQ(*ca, JobState::kRunning);
  EXPECT_TRUE((*store->get(*a))->cancel_requested);
  auto cb = store->request_cancel(*b);
  ASSERT_TRUE(cb);
  EXPECT_EQ(*cb, JobState::kCancelled);
  ASSERT_TRUE(store->set_state(*a, JobState::kCancelled));
  auto again = store->request_cancel(*a);
  ASSERT_FALSE(again);
  EXPECT_NE(again.error().message.find("already ended"), std::string::npos);
  EXPECT_FALSE(store->request_cancel(999));
  // A cancel asked for before a crash is honoured on restart, not re-run.
  auto c = store->enqueue("c", "p", "o", "cli");
  ASSERT_TRUE(store->claim_next());
  ASSERT_TRUE(store->request_cancel(*c));
  ASSERT_TRUE(store->requeue_interrupted());
  EXPECT_EQ((*store->get(*c))->state, JobState::kCancelled);
}

TEST(JobStore, StagesAreRecordedInOrder) {
  auto dir = tp::test::scratch_dir("store-stages");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto id = store->enqueue("a", "p", "o", "cli");
  ASSERT_TRUE(store->set_stage(*id, "pattern", "done", 0.5));
  ASSERT_TRUE(store->set_stage(*id, "print", "running", 0));
  ASSERT_TRUE(store->set_stage(*id, "print", "done", 3.0));
  auto st = store->stages(*id);
  ASSERT_TRUE(st);
  ASSERT_EQ(st->size(), 2u);
  EXPECT_EQ((*st)[1].stage, "print");
  EXPECT_EQ((*st)[1].state, "done");
  EXPECT_DOUBLE_EQ((*st)[1].seconds, 3.0);
  EXPECT_EQ((*store->get(*id))->stage, "print");
}

TEST(JobStore, FatalCrashMarksTheJobFailedInsteadOfRequeueingIt) {
  auto dir = tp::test::scratch_dir("store-crash");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto id = store->enqueue("a", "p", "o", "cli");
  ASSERT_TRUE(store->claim_next());
  auto st = store->record_crash(*id, "printd crashed (SIGABRT) in stage outputs", 1);
  ASSERT_TRUE(st) << st.error().message;
  EXPECT_EQ(*st, JobState::kFailed);
  auto rec = store->get(*id);
  EXPECT_EQ((*rec)->crash_count, 1);
  EXPECT_EQ((*rec)->error, "printd crashed (SIGABRT) in stage outputs");
  // Nothing left running, so a restart queues nothing: no crash loop.
  auto n = store->requeue_interrupted();
  ASSERT_TRUE(n);
  EXPECT_EQ(n->requeued, 0);
  EXPECT_EQ((*store->get(*id))->state, JobState::kFailed);
  // With a higher limit the first crash re-queues it.
  auto b = store->enqueue("b", "p", "o", "cli");
  ASSERT_TRUE(store->claim_next());
  EXPECT_EQ(*store->record_crash(*b, "x", 2), JobState::kQueued);
}

TEST(JobStore, RepeatedUncleanExitsEndInFailedNotALoop) {
  auto dir = tp::test::scratch_dir("store-unclean");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto id = store->enqueue("a", "p", "o", "cli");
  for (int restart = 1; restart <= 2; ++restart) {
    ASSERT_TRUE(store->claim_next());
    auto n = store->requeue_interrupted(2);
    ASSERT_TRUE(n);
    EXPECT_EQ(n->requeued, 1) << restart;
  }
  ASSERT_TRUE(store->claim_next());
  auto n = store->requeue_interrupted(2);
  ASSERT_TRUE(n);
  EXPECT_EQ(n->failed, 1);
  auto rec = store->get(*id);
  EXPECT_EQ((*rec)->state, JobState::kFailed);
  EXPECT_EQ((*rec)->unclean_exits, 3);
  EXPECT_NE((*rec)->error.find("--max-unclean-exits=2"), std::string::npos) << (*rec)->error;
  // A clean shutdown releases the job without counting.
  auto b = store->enqueue("b", "p", "o", "cli");
  ASSERT_TRUE(store->claim_next());
  ASSERT_TRUE(store->release(*b));
  EXPECT_EQ((*store->get(*b))->state, JobState::kQueued);
  EXPECT_EQ((*store->get(*b))->unclean_exits, 0);
}

TEST(JobStore, LiveJobIsFoundByContentHash) {
  auto dir = tp::test::scratch_dir("store-hash");
  auto store = JobStore::open(dir / "jobs.db");
  ASSERT_TRUE(store);
  auto id = store->enqueue("a", "p", "o", "socket", "abc123");
  auto found = store->find_live_by_hash("abc123");
  ASSERT_TRUE(found && *found);
  EXPECT_EQ((*found)->id, *id);
  EXPECT_FALSE(*store->find_live_by_hash(""));
  // A failed job is not a reason to refuse a retry.
  ASSERT_TRUE(store->set_state(*id, JobState::kFailed, "x"));
  EXPECT_FALSE(*store->find_live_by_hash("abc123"));
}

TEST(JobStore, UnopenableDatabaseIsReported) {
  auto st = JobStore::open("/nonexistent-dir/jobs.db");
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("/nonexistent-dir/jobs.db"), std::string::npos);
}

}  // namespace
}  // namespace tp::host
