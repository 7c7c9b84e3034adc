// tests/host/session/print_session_test.cpp: the print session against the real firmware in
// process (no USB): checkpoints, resume, credits, unplug/replug, faults, pauses, cancellation.
#include "host/session/print_session.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <thread>

#include "device/firmware/controller.h"
#include "device/firmware/firmware_transport.h"
#include "host/session/sim_reexec.h"
#include "host/session/synthetic_run.h"

namespace tp::host {
namespace {

using std::chrono::milliseconds;

struct Fabric : device::PrintSink {
  std::vector<std::uint32_t> printed;
  void job_started(const device::JobBeginMsg&, bool) override {}
  void swath_printed(const device::SwathHeader& h, std::span<const std::uint8_t>, std::int64_t) override {
    printed.push_back(h.index);
  }
  void job_finished(const device::JobReportMsg&) override {}
};

device::PrinterModel model(int slots = 4) {
  device::PrinterModel m;
  m.nozzles_per_ink = 16;
  m.swath_buffer_slots = static_cast<std::uint16_t>(slots);
  m.swath_buffer_bytes = 1u << 20;
  return m;
}

struct Rig {
  Fabric fabric;
  device::PrinterController printer;
  device::FirmwareTransport* transport = nullptr;  // owned by the session
  std::unique_ptr<PrintSession> session;
  explicit Rig(device::PrinterModel m = model(), device::FirmwareOptions fo = {}) : printer(std::move(m), &fabric, fo) {}
  void open(PrinterConfig cfg = {}) {
    auto t = std::make_unique<device::FirmwareTransport>(printer);
    transport = t.get();
    cfg.use_gpio = false;
    cfg.link.retransmit_timeout = milliseconds(100);
    auto s = PrintSession::open_with(std::move(t), cfg);
    ASSERT_TRUE(s) << s.error().message;
    session = std::move(*s);
  }
};

SyntheticRunOptions job(std::uint32_t swaths) {
  SyntheticRunOptions o;
  o.job.swaths = swaths;
  o.job.width_px = 64;
  o.job.x_start_px = 8;
  o.job.cue_every = 3;
  o.job_id = 77;
  return o;
}

std::vector<std::uint32_t> range(std::uint32_t from, std::uint32_t to) {
  std::vector<std::uint32_t> v;
  for (std::uint32_t i = from; i < to; ++i) v.push_back(i);
  return v;
}

TEST(PrintSession, RunsAJobWithCheckpointsInOrderAndCuesWithinAFeedStep) {
  Rig r;
  r.open();
  std::vector<std::uint32_t> acked;
  r.session->on_swath_acked([&](std::uint32_t i) { acked.push_back(i); });
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, job(9), cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(acked, range(0, 9));
  EXPECT_EQ(r.fabric.printed, range(0, 9));
  EXPECT_EQ(res->job.report.swaths_printed, 9u);
  EXPECT_EQ(res->job.report.overruns, 0u);
  const std::int64_t feed_um = synthetic_position_um(job(9).job, r.session->printer(), 1);
  ASSERT_EQ(res->job.cues.size(), 6u);
  for (const auto& c : res->job.cues) {
    EXPECT_TRUE(c.fired) << "cue " << c.id;
    EXPECT_GE(c.fired_at_um, c.position_um) << "cue " << c.id;
    EXPECT_LT(c.fired_at_um - c.position_um, feed_um) << "cue " << c.id;
  }
  EXPECT_EQ(res->job.report.cues_fired, 6u);
}

// Drops per ink of a clean run of `o` on a fresh printer.
std::vector<std::uint64_t> clean_drops(const SyntheticRunOptions& o) {
  Rig clean;
  clean.open();
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*clean.session, o, cancel);
  EXPECT_TRUE(res) << res.error().message;
  return res ? res->job.report.drops_per_ink : std::vector<std::uint64_t>{};
}

TEST(PrintSession, ResumesAJobThePrinterLostFromItsLastPrintedSwath) {
  Rig r;
  r.open();
  bool lost = false;
  r.printer.set_observer([&](const device::FirmwareEvent& e) {
    if (e.kind == device::FirmwareEventKind::kSwathPrinting && e.swath == 4 && !lost) {
      lost = true;  // the operator clears the printer as swath 4 is about to print
      r.printer.lose_job("buffer cleared");
    }
  });
  std::vector<std::uint32_t> printed;
  r.session->on_swath_printed([&](std::uint32_t i, std::int64_t) { printed.push_back(i); });
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, job(9), cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_TRUE(lost);
  EXPECT_EQ(r.fabric.printed, range(0, 9)) << "nothing lost, nothing printed twice";
  EXPECT_EQ(res->job.stats.lost_job_resumes, 1u);
  EXPECT_EQ(res->job.report.swaths_printed, 9u) << "the printer's counters go on across the loss";
  EXPECT_EQ(res->job.report.drops_per_ink, clean_drops(job(9)));
  EXPECT_EQ(res->job.report.cues_fired, 6u) << "no cue fired twice or missed";
  ASSERT_FALSE(printed.empty());
  EXPECT_EQ(printed.back(), 8u);
}

// A host that dies after handing in swaths 0..n-1: its session is dropped without aborting.
void host_dies_after(Rig& r, const SyntheticRunOptions& o, std::uint32_t n) {
  JobStart start{o.job_id, o.name, 0, 80};
  ASSERT_TRUE(r.session->begin_job(start));
  geometry::CancelToken cancel;
  for (std::uint32_t i = 0; i < n; ++i)
    ASSERT_TRUE(r.session->send_swath(make_synthetic_swath(o.job, r.session->printer(), i), cancel));
  for (int i = 0; i < 50 && r.printer.status().printed_next < n; ++i) std::this_thread::sleep_for(milliseconds(2));
  (void)r.session.release();  // leaked on purpose: a dead process does not abort its job
}

TEST(PrintSession, ANewSessionResumesAJobLostWithThePowerAfterItsLastPrintedSwath) {
  auto o = job(9);
  o.job.cue_every = 0;
  Rig r;
  r.open();
  host_dies_after(r, o, 6);
  r.printer.lose_job("power loss");
  ASSERT_EQ(r.printer.status().last_printed_next, 6u);
  r.open();
  auto o2 = o;
  o2.first_swath = 3;  // the host's checkpoint is behind the printer's record
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, o2, cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(r.fabric.printed, range(0, 9));
  EXPECT_EQ(r.session->stats().swaths_skipped, 6u);
  EXPECT_EQ(res->job.report.swaths_printed, 9u);
  EXPECT_EQ(res->job.report.drops_per_ink, clean_drops(o));
}

TEST(PrintSession, ANewSessionReattachesToTheJobThePrinterStillHolds) {
  auto o = job(9);
  o.job.cue_every = 0;
  Rig r;
  r.open();
  host_dies_after(r, o, 4);
  r.open();
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, o, cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_TRUE(res->job.stats.reattached);
  EXPECT_EQ(r.fabric.printed, range(0, 9));
  EXPECT_EQ(res->job.report.drops_per_ink, clean_drops(o));
}

TEST(PrintSession, AReattachedJobWaitsForCreditWhileThePrinterStillHoldsAFullBuffer) {
  // The printer is paused with its 3-slot buffer full when the host dies; the new session knows
  // the printer holds swaths 0-2 only from its status, and must not send swath 3 before one of
  // them is printed (the printer refuses a swath sent without credit).
  auto o = job(6);
  o.job.cue_every = 0;
  Rig r(model(3));
  r.open();
  r.printer.set_condition(device::PrinterCondition::kInkLow, true);
  JobStart start{o.job_id, o.name, 0, 80};
  ASSERT_TRUE(r.session->begin_job(start));
  geometry::CancelToken cancel;
  for (std::uint32_t i = 0; i < 3; ++i)
    ASSERT_TRUE(r.session->send_swath(make_synthetic_swath(o.job, r.session->printer(), i), cancel));
  (void)r.session.release();  // leaked on purpose: a dead process does not abort its job
  ASSERT_EQ(r.printer.status().swath_next, 3u);
  ASSERT_EQ(r.printer.status().free_slots, 0u);
  r.open();
  std::thread clear([&] {
    std::this_thread::sleep_for(milliseconds(200));
    r.transport->with_controller(
        [](device::PrinterController& c) { c.set_condition(device::PrinterCondition::kInkLow, false); });
  });
  auto res = run_synthetic_job(*r.session, o, cancel);
  clear.join();
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_TRUE(res->job.stats.reattached);
  EXPECT_GT(res->job.stats.credit_wait_s, 0.1);
  EXPECT_EQ(r.fabric.printed, range(0, 6));
  EXPECT_EQ(res->job.report.overruns, 0u);
  EXPECT_EQ(res->job.report.drops_per_ink, clean_drops(o));
}

TEST(PrintSession, AJobThePrinterCompletedIsNotPrintedAgain) {
  auto o = job(5);
  o.job.cue_every = 0;
  Rig r;
  r.open();
  geometry::CancelToken cancel;
  ASSERT_TRUE(run_synthetic_job(*r.session, o, cancel));
  r.open();
  auto res = run_synthetic_job(*r.session, o, cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(r.fabric.printed, range(0, 5));
  EXPECT_TRUE(r.session->finished_on_printer());
  EXPECT_EQ(res->job.report.swaths_printed, 5u);
}

TEST(PrintSession, ACheckpointThePrinterHasNoRecordOfStopsWithAnOperatorMessage) {
  Rig r;
  r.open();
  auto o = job(8);
  o.first_swath = 5;
  o.job.cue_every = 0;
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, o, cancel);
  ASSERT_FALSE(res);
  EXPECT_EQ(res.error().code, ErrorCode::kPrinter);
  EXPECT_NE(res.error().message.find("no record"), std::string::npos) << res.error().message;
  EXPECT_NE(res.error().message.find("print the job again"), std::string::npos) << res.error().message;
  EXPECT_TRUE(r.fabric.printed.empty());
}

TEST(PrintSession, WaitsForCreditInsteadOfOverrunningTheBuffer) {
  device::FirmwareOptions fo;
  fo.speed = 20;  // passes take real (if short) time: the 2-slot buffer fills
  Rig r(model(2), fo);
  r.open();
  geometry::CancelToken cancel;
  auto o = job(6);
  o.job.cue_every = 0;
  auto res = run_synthetic_job(*r.session, o, cancel);
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(res->job.report.overruns, 0u);
  EXPECT_GT(res->job.stats.credit_wait_s, 0.0);
  EXPECT_EQ(r.fabric.printed, range(0, 6));
}

TEST(PrintSession, SurvivesAnUnplugMidSwathWithNothingLostOrPrintedTwice) {
  Rig r;
  r.open();
  std::thread replug;
  r.printer.set_observer([&](const device::FirmwareEvent& e) {
    if (e.kind == device::FirmwareEventKind::kSwathHeader && e.swath == 4 && !replug.joinable()) {
      r.transport->set_connected(false);
      replug = std::thread([&] {
        std::this_thread::sleep_for(milliseconds(150));
        r.transport->set_connected(true);
      });
    }
  });
  std::vector<std::uint32_t> acked;
  r.session->on_swath_acked([&](std::uint32_t i) { acked.push_back(i); });
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, job(9), cancel);
  if (replug.joinable()) replug.join();
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(r.fabric.printed, range(0, 9));
  EXPECT_EQ(acked, range(0, 9));
  EXPECT_EQ(res->job.stats.reconnects, 1u);
  EXPECT_GE(res->job.stats.recovery_ms_last, 100.0);
  EXPECT_GE(res->job.stats.swaths_resent, 1u);
}

TEST(PrintSession, APrinterFaultEndsTheJobNamingItAndWhatWasPrinted) {
  Rig r;
  r.printer.set_observer([&](const device::FirmwareEvent& e) {
    if (e.kind == device::FirmwareEventKind::kSwathPrinting && e.swath == 3)
      r.printer.raise_fault(device::PrinterCondition::kMediaJam);
  });
  r.open();
  geometry::CancelToken cancel;
  auto res = run_synthetic_job(*r.session, job(8), cancel);
  ASSERT_FALSE(res);
  EXPECT_EQ(res.error().code, ErrorCode::kPrinter);
  EXPECT_NE(res.error().message.find("media jam"), std::string::npos) << res.error().message;
  EXPECT_NE(res.error().message.find("below 3 printed"), std::string::npos) << res.error().message;
  EXPECT_EQ(r.fabric.printed, range(0, 3));
  EXPECT_EQ(r.printer.state(), device::PrinterState::kIdle) << "the session aborts the failed job";
}

TEST(PrintSession, APauseIsWaitedOut) {
  Rig r;
  r.open();
  std::thread clear;
  r.printer.set_observer([&](const device::FirmwareEvent& e) {
    if (e.kind == device::FirmwareEventKind::kSwathPrinting && e.swath == 2 && !clear.joinable()) {
      r.printer.set_condition(device::PrinterCondition::kInkLow, true);
      clear = std::thread([&] {
        std::this_thread::sleep_for(milliseconds(200));
        r.transport->with_controller(
            [](device::PrinterController& c) { c.set_condition(device::PrinterCondition::kInkLow, false); });
      });
    }
  });
  geometry::CancelToken cancel;
  auto o = job(6);
  o.job.cue_every = 0;
  auto res = run_synthetic_job(*r.session, o, cancel);
  if (clear.joinable()) clear.join();
  ASSERT_TRUE(res) << res.error().message;
  EXPECT_EQ(r.fabric.printed, range(0, 6));
  EXPECT_GT(res->job.stats.pause_s, 0.1);
}

TEST(PrintSession, CancellingAbortsTheJobOnThePrinter) {
  Rig r;
  r.open();
  geometry::CancelToken cancel;
  std::vector<std::uint32_t> acked;
  r.session->on_swath_acked([&](std::uint32_t i) {
    acked.push_back(i);
    if (i == 2) cancel.cancel();
  });
  auto res = run_synthetic_job(*r.session, job(9), cancel);
  ASSERT_FALSE(res);
  EXPECT_EQ(res.error().code, ErrorCode::kCancelled);
  EXPECT_LT(r.fabric.printed.size(), 9u);
  auto st = r.printer.status();
  EXPECT_EQ(st.state, device::PrinterState::kIdle);
  EXPECT_EQ(st.last_outcome, device::JobOutcome::kAborted);
}

TEST(PrintSession, RefusesAnIncompatiblePrinter) {
  auto m = model();
  m.protocol_version = 7;
  Rig r(m);
  auto t = std::make_unique<device::FirmwareTransport>(r.printer);
  PrinterConfig cfg;
  cfg.use_gpio = false;
  auto s = PrintSession::open_with(std::move(t), cfg);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kPrinter);
  EXPECT_NE(s.error().message.find("speaks protocol version 7; this host speaks 1"), std::string::npos)
      << s.error().message;
}

TEST(PrintSession, RefusesJobIdZeroWhichThePrinterReportsAsNoJob) {
  Rig r;
  r.open();
  JobStart js;
  js.name = "zero";
  auto st = r.session->begin_job(js);
  ASSERT_FALSE(st);
  EXPECT_EQ(st.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(st.error().message.find("job id 0"), std::string::npos) << st.error().message;
  js.job_id = 1;
  EXPECT_TRUE(r.session->begin_job(js)) << "a numbered job still opens";
}

TEST(PrintSession, RefusesThePrintsimPrinterOutsidePrintsim) {
  if (under_printsim()) GTEST_SKIP() << "running under printsim";
  PrinterConfig cfg;
  cfg.printer = PrinterChoice::kSim;
  auto s = PrintSession::open(cfg);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("printsim run"), std::string::npos) << s.error().message;
}

}  // namespace
}  // namespace tp::host
