// tests/scenarios/http/printer_fault_test.cpp: printd under printsim with the head cover opened
// mid-print: GET /api/v1/printer shows the live printer (identity, the fault as it happens, swath
// buffer, counters, cutter lines) and the event stream carries `printer` events for the change.
#include <gtest/gtest.h>
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

TEST(HttpPrinterFault, CoverOpenShowsInPrinterRouteAndEvents) {
  const fs::path root = fs::temp_directory_path() / ("tp-http-fault-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "hot");
  // The shirt front in four passes (13 swaths), a reproducible nesting budget.
  const fs::path job = root / "fault-shirt";
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  json j = json::parse(read_text(job / "job.json"));
  j["name"] = "fault-shirt";
  j["marker"].erase("time_limit_s");
  j["marker"]["budget"] = {{"iterations", 200}};
  j["print"]["passes"] = 4;
  std::ofstream(job / "job.json") << j.dump(2);
  // The built-in printer at the job's 150 dpi, its cover opened for 1.5 s as swath 4 prints.
  std::string model = run_command({(bin_dir() / "printsim").string(), "model"}).output;
  for (const char* key : {"dpi_x = 600", "dpi_y = 600"}) {
    const auto at = model.find(key);
    if (at != std::string::npos) model.replace(at + 8, 3, "150");
  }
  std::ofstream(root / "printer.tpm") << model;
  std::ofstream(root / "fault.json")
      << R"({"description": "cover open", "faults": [{"type": "cover_open", "at_swath": 4, "duration_ms": 1500}]})";
  std::ofstream(root / "printd.sh") << "#!/bin/sh\necho $$ > \"$1/printd.pid\"\nexec \"$2\" --state-dir \"$1/state\" "
                                       "--hot-folder \"$1/hot\" --out \"$1/out\" --printer sim --poll-ms 100 "
                                       "--listen 127.0.0.1:0 >> \"$1/printd.log\" 2>&1\n";
  std::fflush(stdout);
  const pid_t sim = ::fork();
  if (sim == 0) {
    const std::string log = (root / "printsim.log").string();
    if (std::freopen(log.c_str(), "a", stdout)) ::dup2(::fileno(stdout), 2);
    const std::string simexe = (bin_dir() / "printsim").string(), tpm = (root / "printer.tpm").string(),
                      scen = (root / "fault.json").string(), out = (root / "sim").string(),
                      sh = (root / "printd.sh").string(), r = root.string(), printd = (bin_dir() / "printd").string();
    ::execl(simexe.c_str(), simexe.c_str(), "run", "--job-dirs", "--printer", tpm.c_str(), "--speed", "2",
            "--scenario", scen.c_str(), "--out", out.c_str(), "--", "/bin/sh", sh.c_str(), r.c_str(), printd.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int port = 0;
  const std::regex port_re(R"(HTTP API on http://127\.0\.0\.1:(\d+))");
  for (int i = 0; i < 400 && port == 0; ++i) {
    std::smatch m;
    const std::string log = read_text(root / "printd.log");
    if (std::regex_search(log, m, port_re)) port = std::stoi(m[1]);
    else std::this_thread::sleep_for(50ms);
  }
  ASSERT_NE(port, 0) << read_text(root / "printd.log") << read_text(root / "printsim.log");
  ASSERT_EQ(run_command({(bin_dir() / "printctl").string(), "submit", job.string(), "--state-dir",
                         (root / "state").string()})
                .exit_code,
            0);

  // Poll the printer route while the job prints: the cover fault must show as it happens.
  httplib::Client c("127.0.0.1", port);
  c.set_read_timeout(10, 0);
  json during_fault, last;
  std::string job_state;
  const auto deadline = std::chrono::steady_clock::now() + 240s;
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto r = c.Get("/api/v1/printer"); r && r->status == 200) {
      last = json::parse(r->body);
      const json& dev = last["device"];
      if (dev.is_object() && dev.value("condition", "") == "cover_open" && during_fault.is_null()) during_fault = last;
    }
    if (auto r = c.Get("/api/v1/jobs/1"); r && r->status == 200) job_state = json::parse(r->body)["job"].value("state", "");
    if (job_state == "done" || job_state == "failed" || job_state == "cancelled") break;
    std::this_thread::sleep_for(20ms);
  }
  EXPECT_EQ(job_state, "done") << read_text(root / "printd.log");
  ASSERT_TRUE(during_fault.is_object()) << "never saw the cover open; last: " << last.dump();
  const json& dev = during_fault["device"];
  EXPECT_EQ(dev["state"], "paused") << dev.dump();
  ASSERT_EQ(dev["faults"].size(), 1u) << dev.dump();
  EXPECT_EQ(dev["faults"][0]["condition"], "cover_open");
  EXPECT_NE(dev["faults"][0]["text"].get<std::string>().find("cover"), std::string::npos);
  EXPECT_NE(dev["identity"]["ieee1284_id"].get<std::string>().find("CMD:TPWP;"), std::string::npos) << dev.dump();
  EXPECT_GT(dev["swath_buffer"]["slots"].get<int>(), 0);
  EXPECT_GT(dev["swath_buffer"]["bytes"].get<int>(), 0);
  EXPECT_GE(dev["counters"]["swaths_committed"].get<int>(), 4);
  // After the job: every swath printed, the cover closed again, cues fired on the cutter lines.
  const json& end = last["device"];
  EXPECT_EQ(end["condition"], "none") << end.dump();
  EXPECT_TRUE(end["faults"].empty());
  EXPECT_EQ(end["counters"]["swaths_printed"], 13) << end.dump();
  ASSERT_FALSE(end["cutter_lines"].empty()) << end.dump();
  EXPECT_EQ(end["cutter_lines"][0]["line"], "cutter_cue");

  // The events: printer events for the cover opening and closing, in order.
  std::vector<json> printer_events;
  std::string buffer;
  httplib::Client ev("127.0.0.1", port);
  ev.set_read_timeout(30, 0);
  ev.Get("/api/v1/events?after=0", [&](const char* data, size_t n) {
    buffer.append(data, n);
    size_t e;
    while ((e = buffer.find("\n\n")) != std::string::npos) {
      const std::string frame = buffer.substr(0, e);
      buffer.erase(0, e + 2);
      const size_t d0 = frame.find("data: ");
      if (d0 == std::string::npos) continue;
      const json ej = json::parse(frame.substr(d0 + 6));
      if (ej["type"] == "printer") printer_events.push_back(ej);
      if (ej["type"] == "job" && ej["state"] == "done") return false;
    }
    return true;
  });
  int open_at = -1, closed_at = -1;
  for (size_t k = 0; k < printer_events.size(); ++k) {
    if (printer_events[k].value("condition", "") == "cover_open" && open_at < 0) open_at = static_cast<int>(k);
    if (open_at >= 0 && printer_events[k].value("condition", "") == "none" && closed_at < 0)
      closed_at = static_cast<int>(k);
  }
  ASSERT_GE(open_at, 0) << json(printer_events).dump();
  EXPECT_EQ(printer_events[open_at]["state"], "paused");
  EXPECT_EQ(printer_events[open_at]["faults"][0]["condition"], "cover_open");
  EXPECT_GT(closed_at, open_at) << json(printer_events).dump();

  const pid_t printd = std::stoi(read_text(root / "printd.pid"));
  ::kill(printd, SIGTERM);
  int st = 0;
  ::waitpid(sim, &st, 0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace tp::test
