// tests/drivers/usb/usb_transport_test.cpp: the libusb transport against printsim's emulated
// printer: finding it by device ID, refusing other printers, streaming frames, a stall cleared
// and resent, and an unplug/replug.
#include "drivers/usb/usb_transport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "device/protocol/host_link.h"
#include "tests/drivers/under_printsim.h"

namespace tp::drivers {
namespace {

using std::chrono::milliseconds;

device::Swath swath(std::uint32_t i) {
  device::Swath s;
  s.header.index = i;
  s.header.rows = 64;
  s.header.first_row = i * 64;
  s.header.feed_before_um = i ? 2709 : 0;
  s.header.width_px = 4000;
  s.header.channels = 4;
  s.header.raw_bytes = static_cast<std::uint32_t>(device::swath_raw_bytes(s.header));
  s.data.resize(s.header.raw_bytes);
  for (std::size_t k = 0; k < s.data.size(); ++k) s.data[k] = static_cast<std::uint8_t>((k * 31 + i) & 0x55);
  return s;
}

// Runs a small job through the link and returns the printer's report.
device::JobReportMsg run_job(device::HostLink& link, std::uint32_t swaths) {
  EXPECT_TRUE(link.send_msg(device::MessageType::kJobBegin, device::JobBeginMsg{9, "usb-test", 0, 4100}));
  for (std::uint32_t i = 0; i < swaths; ++i) EXPECT_TRUE(link.send_swath(swath(i)));
  EXPECT_TRUE(link.send_msg(device::MessageType::kJobEnd, device::JobEndMsg{swaths, 0}));
  for (int k = 0; k < 500; ++k) {
    EXPECT_TRUE(link.poll(milliseconds(10)));
    if (auto r = link.take_report()) return *r;
  }
  ADD_FAILURE() << "no job report";
  return {};
}

TEST(UsbTransport, FindsThePrinterByDeviceIdAndStreamsAJob) {
  if (!test::rerun_under_printsim()) return;
  auto t = UsbTransport::open({}, milliseconds(2000));
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_NE((*t)->device_id().find("CMD:TPWP"), std::string::npos);
  EXPECT_NE((*t)->describe().find("1d6b:0104"), std::string::npos) << (*t)->describe();
  auto port = (*t)->port_status();
  ASSERT_TRUE(port);
  EXPECT_EQ(*port & 0x18, 0x18) << "selected, no error";
  device::HostLink link(**t);
  auto id = link.handshake();
  ASSERT_TRUE(id) << id.error().message;
  EXPECT_EQ(id->model, "tp-sim-1600");
  const auto report = run_job(link, 3);
  EXPECT_EQ(report.swaths_printed, 3u);
  EXPECT_EQ(link.stats().frames_resent, 0u);
  EXPECT_GE((*t)->stats().out_bytes, 3u * swath(0).data.size());
}

TEST(UsbTransport, RefusesPrintersThatDoNotMatch) {
  if (!test::rerun_under_printsim()) return;
  UsbOptions o;
  o.match.ieee1284 = "MDL:SOMETHING-ELSE;";
  auto t = UsbTransport::open(o);
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().code, ErrorCode::kNotFound);
  EXPECT_NE(t.error().message.find("MDL:SOMETHING-ELSE"), std::string::npos) << t.error().message;
  EXPECT_NE(t.error().message.find("TP-SIM-1600"), std::string::npos) << "names the printers it saw";
  UsbOptions v;
  v.match.vendor_id = 0x1234;
  auto t2 = UsbTransport::open(v);
  ASSERT_FALSE(t2);
  EXPECT_NE(t2.error().message.find("1234"), std::string::npos) << t2.error().message;
}

TEST(UsbTransport, ClearsAStallAndResendsInOrder) {
  const auto scenario = test::scratch_dir("stall-scenario") / "stall.json";
  std::ofstream(scenario) << R"({"faults": [{"type": "stall", "at_swath": 1}]})";
  std::filesystem::path out;
  if (!test::rerun_under_printsim({"--scenario", scenario.string()}, &out)) {
    std::ifstream in(out / "printsim.json");
    auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["usb"]["stalls"], 1) << "the fault fired";
    EXPECT_GE(j["usb"]["halts_cleared"].get<int>(), 1) << "the driver cleared the halt";
    return;
  }
  auto t = UsbTransport::open({}, milliseconds(2000));
  ASSERT_TRUE(t) << t.error().message;
  device::HostLink link(**t);
  ASSERT_TRUE(link.handshake());
  const auto report = run_job(link, 4);
  EXPECT_EQ(report.swaths_printed, 4u) << "the stalled data was resent, nothing lost";
  EXPECT_EQ((*t)->stats().stalls, 1u);
}

TEST(UsbTransport, ReconnectsAfterAnUnplug) {
  const auto scenario = test::scratch_dir("unplug-scenario") / "unplug.json";
  std::ofstream(scenario) << R"({"faults": [{"type": "unplug", "at_swath": 1, "duration_ms": 300}]})";
  if (!test::rerun_under_printsim({"--scenario", scenario.string()})) return;
  auto t = UsbTransport::open({}, milliseconds(2000));
  ASSERT_TRUE(t) << t.error().message;
  device::HostLink link(**t);
  ASSERT_TRUE(link.handshake());
  ASSERT_TRUE(link.send_msg(device::MessageType::kJobBegin, device::JobBeginMsg{9, "usb-test", 0, 4100}));
  device::Status failed;
  for (std::uint32_t i = 0; i < 6 && failed; ++i) {
    failed = link.send_swath(swath(i));
    for (int k = 0; k < 20 && failed; ++k) failed = link.poll(milliseconds(10));
  }
  ASSERT_FALSE(failed) << "the unplug reached the host";
  EXPECT_EQ(failed.error().code, device::ErrorCode::kDisconnected) << failed.error().message;
  const auto t0 = std::chrono::steady_clock::now();
  auto r = (*t)->reconnect(milliseconds(5000));
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_GE(std::chrono::steady_clock::now() - t0, milliseconds(150)) << "the printer stayed away ~300 ms";
  EXPECT_NE((*t)->describe().find("1:3"), std::string::npos) << "a new device address: " << (*t)->describe();
  auto id = link.handshake();
  ASSERT_TRUE(id) << id.error().message;
  auto st = link.query_status(milliseconds(2000));
  ASSERT_TRUE(st);
  EXPECT_EQ(st->job_id, 9u) << "the printer kept the job across the unplug";
  EXPECT_EQ((*t)->stats().reconnects, 1u);
}

}  // namespace
}  // namespace tp::drivers
