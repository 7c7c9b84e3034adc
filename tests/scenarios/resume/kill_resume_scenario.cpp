// tests/scenarios/resume/kill_resume_scenario.cpp: the host killed with SIGKILL mid-print at five
// points (and printsim killed, a printer losing power) and started again: the final fabric must
// equal a clean run's drop for drop per ink, with no swath missing or printed twice. The host runs
// under printsim in a restart loop (as a service manager would run it); printsim keeps its memory
// in --state. Two hosts: `printctl link-job` with a synthetic job (no planning: exact equality),
// and printd with a garment job whose marker has an iteration budget (`marker.budget`), so the
// clean run and every killed run plan the same marker; a resumed run reuses the job's stored plan.
#include <OpenImageIO/imageio.h>
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
using Clock = std::chrono::steady_clock;

const char* const kJobName = "resume-shirt";

// The flat shirt front in four passes: 13 swaths of a one-piece marker.
fs::path make_job(const fs::path& dir) {
  const fs::path job = dir / kJobName;
  fs::create_directories(dir);
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  json j = read_json_or_null(job / "job.json");
  j["name"] = kJobName;
  // A work budget, not seconds: separate runs (the clean one, each killed one) nest the same
  // marker whatever the load, and a resume reuses the stored one.
  j["marker"].erase("time_limit_s");
  j["marker"]["budget"] = {{"iterations", 400}};
  j["print"]["passes"] = 4;
  std::ofstream(job / "job.json") << j.dump(2);
  return job;
}

// printsim with printd restarted in a loop until `stop` exists.
class PrintRoom {
 public:
  /// `synthetic`: the host is `printctl link-job` with a fixed synthetic job (deterministic, no
  /// planning), restarted until it succeeds; otherwise printd with the job store. `speed`:
  /// printsim's modelled seconds per wall second, 2 where the test kills while printing; 0 (as
  /// fast as data arrives) for a clean run, whose fabric does not depend on it.
  explicit PrintRoom(fs::path root, bool synthetic = false, double speed = 2)
      : root_(std::move(root)), synthetic_(synthetic), speed_(speed) {
    fs::create_directories(root_ / "hot");
    if (synthetic)
      std::ofstream(root_ / "loop.sh") << "#!/bin/sh\n"
                                          "while :; do\n"
                                          "  sh -c 'echo $$ > \"$0/printd.pid\"; exec \"$1\" link-job --swaths 9 --rows 128 "
                                          "--width 600 --cue-every 3 --job-id 7 --name synthetic --result \"$0/result.json\"' "
                                          "\"$1\" \"$2\" >> \"$1/printd.log\" 2>&1 && exit 0\n"
                                          "  [ -e \"$1/stop\" ] && exit 1\n"
                                          "  sleep 0.2\n"
                                          "done\n";
    else
    // --max-crashes 2: when printsim is killed, umockdev's preload library in printd aborts on the
    // lost bus socket (SIGABRT, which printd counts as a crash); a real printer unplugged gives
    // libusb's NO_DEVICE instead. The SIGKILLs of printd are unclean exits, not crashes.
    std::ofstream(root_ / "loop.sh") << "#!/bin/sh\n"
                                        "while :; do\n"
                                        "  sh -c 'echo $$ > \"$0/printd.pid\"; exec \"$1\" --state-dir \"$0/state\" "
                                        "--hot-folder \"$0/hot\" --out \"$0/out\" --printer sim --poll-ms 100 "
                                        "--max-crashes 2 --listen 127.0.0.1:0' "
                                        "\"$1\" \"$2\" >> \"$1/printd.log\" 2>&1\n"
                                        "  [ -e \"$1/stop\" ] && exit 0\n"
                                        "  sleep 0.2\n"
                                        "done\n";
    // The printer the job plans for: the built-in model at the job's 150 dpi.
    std::string model = run_command({(bin_dir() / "printsim").string(), "model"}).output;
    for (const char* key : {"dpi_x = 600", "dpi_y = 600"}) {
      const auto at = model.find(key);
      if (at != std::string::npos) model.replace(at + 8, 3, "150");
    }
    std::ofstream(root_ / "printer.tpm") << model;
  }
  ~PrintRoom() {
    if (sim_ > 0) stop();
  }

  void start() {
    fs::remove(root_ / "stop");
    std::fflush(stdout);  // the child must not write our buffered lines again
    sim_ = ::fork();
    if (sim_ == 0) {
      const std::string log = (root_ / "printsim.log").string();
      if (std::freopen(log.c_str(), "a", stdout)) ::dup2(::fileno(stdout), 2);
      const std::string sim = (bin_dir() / "printsim").string(), out = (root_ / "sim").string(),
                        state = (root_ / "printer-memory.json").string(), loop = (root_ / "loop.sh").string(),
                        root = root_.string(), printd = (bin_dir() / "printd").string(),
                        model = (root_ / "printer.tpm").string(), printctl = (bin_dir() / "printctl").string(),
                        speed = std::to_string(speed_);
      if (synthetic_)
        ::execl(sim.c_str(), sim.c_str(), "run", "--speed", "1", "--state", state.c_str(), "--out", out.c_str(), "--",
                "/bin/sh", loop.c_str(), root.c_str(), printctl.c_str(), static_cast<char*>(nullptr));
      else
        ::execl(sim.c_str(), sim.c_str(), "run", "--job-dirs", "--printer", model.c_str(), "--speed", speed.c_str(),
                "--state", state.c_str(), "--out", out.c_str(), "--", "/bin/sh", loop.c_str(), root.c_str(),
                printd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }

  CommandResult ctl(std::vector<std::string> args) const {
    args.insert(args.begin(), (bin_dir() / "printctl").string());
    args.push_back("--state-dir");
    args.push_back((root_ / "state").string());
    return run_command(args);
  }

  bool submit(const fs::path& job) {
    for (int i = 0; i < 200; ++i) {
      if (ctl({"submit", job.string()}).exit_code == 0) return true;
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }

  std::string state() const {
    auto r = ctl({"status", "--json"});
    if (r.exit_code != 0) return "";
    json j = json::parse(r.output, nullptr, false);
    if (j.is_discarded() || !j.contains("jobs") || j["jobs"].empty()) return "";
    return j["jobs"][0].value("state", "");
  }

  std::string wait_end(std::chrono::seconds limit = 300s) const {
    const auto until = Clock::now() + limit;
    std::string s;
    while (Clock::now() < until) {
      s = state();
      if (s == "done" || s == "failed" || s == "cancelled") return s;
      std::this_thread::sleep_for(250ms);
    }
    return s;
  }

  /// Swaths below this are on the fabric, from the printer's memory (-1 before the job).
  int printed_next() const {
    json m = read_json_or_null(root_ / "printer-memory.json");
    return m.is_object() ? m.value("last_printed_next", -1) : -1;
  }

  bool wait_printed(int n, std::chrono::seconds limit = 120s) const {
    const auto until = Clock::now() + limit;
    while (Clock::now() < until) {
      if (printed_next() >= n) return true;
      std::this_thread::sleep_for(10ms);
    }
    return false;
  }

  pid_t printd_pid() const {
    std::ifstream in(root_ / "printd.pid");
    pid_t p = 0;
    in >> p;
    return p;
  }

  void kill_printd() {
    const pid_t p = printd_pid();
    if (p > 0) ::kill(p, SIGKILL);
  }

  /// SIGKILL printsim (the printer loses power), then the host processes it left behind.
  void kill_printsim() {
    std::vector<pid_t> kids;
    std::ifstream in("/proc/" + std::to_string(sim_) + "/task/" + std::to_string(sim_) + "/children");
    for (pid_t k; in >> k;) kids.push_back(k);
    ::kill(sim_, SIGKILL);
    ::waitpid(sim_, nullptr, 0);
    sim_ = -1;
    for (pid_t k : kids) ::kill(k, SIGKILL);
    kill_printd();
    std::this_thread::sleep_for(300ms);
  }

  void stop() {
    std::ofstream(root_ / "stop") << "\n";
    const pid_t p = printd_pid();
    if (p > 0) ::kill(p, SIGTERM);
    int st = 0;
    if (sim_ > 0) ::waitpid(sim_, &st, 0);
    sim_ = -1;
  }

  const fs::path& root() const { return root_; }

  /// Waits for printsim to end by itself (the synthetic host loop exits once a run succeeds).
  void wait_exit(std::chrono::seconds limit = 120s) {
    const auto until = Clock::now() + limit;
    while (sim_ > 0 && Clock::now() < until) {
      if (::waitpid(sim_, nullptr, WNOHANG) == sim_) {
        sim_ = -1;
        return;
      }
      std::this_thread::sleep_for(50ms);
    }
  }

 private:
  fs::path root_;
  bool synthetic_ = false;
  double speed_ = 2;
  pid_t sim_ = -1;
};

struct Outcome {
  std::string state;
  std::vector<std::uint64_t> fabric_sum;  ///< per ink: sum of drop levels laid on the fabric
  std::vector<std::uint64_t> drops;       ///< per ink: the printer's drop counters
  std::uint64_t swaths_printed = 0;
  std::vector<std::uint8_t> pixels;
  int width = 0, height = 0;
  double marker_mm = 0;  ///< the marker the (last) run planned
};

Outcome collect(const PrintRoom& room, bool synthetic = false) {
  Outcome o;
  const fs::path dir = synthetic ? room.root() / "sim" : room.root() / "sim" / (std::string("1-") + kJobName);
  const json report = read_json_or_null(room.root() / "out" / kJobName / "report.json");
  if (report.is_object() && report.contains("marker")) o.marker_mm = report["marker"].value("length_mm", 0.0);
  const json printer = read_json_or_null(dir / "printer.json");
  if (printer.is_object()) {
    const json c = printer.value("counters", json::object());
    o.swaths_printed = c.value("swaths_printed", 0u);
    for (const auto& ink : printer["printer"]["inks"]) o.drops.push_back(c["drops_per_ink"].value(ink.get<std::string>(), 0ull));
  }
  OIIO::ImageSpec raw_config;
  raw_config.attribute("oiio:RawColor", 1);  // separated CMYK: the ink samples, not RGB
  auto in = OIIO::ImageInput::open((dir / "fabric.tif").string(), &raw_config);
  if (!in) return o;
  const OIIO::ImageSpec& spec = in->spec();
  o.width = spec.width;
  o.height = spec.height;
  o.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, o.pixels.data())) o.pixels.clear();
  o.fabric_sum.assign(static_cast<std::size_t>(spec.nchannels), 0);
  for (std::size_t i = 0; i < o.pixels.size(); ++i) o.fabric_sum[i % static_cast<std::size_t>(spec.nchannels)] += o.pixels[i];
  return o;
}

std::string row(const std::string& name, const Outcome& o) {
  std::string s = name + ":";
  for (std::size_t i = 0; i < o.drops.size(); ++i)
    s += " " + std::to_string(o.drops[i]) + "/" + (i < o.fabric_sum.size() ? std::to_string(o.fabric_sum[i]) : "?");
  char marker[48];
  std::snprintf(marker, sizeof marker, " marker=%.4f mm", o.marker_mm);
  return s + " swaths_printed=" + std::to_string(o.swaths_printed) + " state=" + o.state + marker;
}

// Prints the job once, killing printd (or printsim) when the printer has printed `kill_at`
// swaths; -1 is the clean run.
Outcome print_with_kill(const std::string& name, int kill_at, bool kill_printsim) {
  PrintRoom room(scratch_dir("kill-resume-" + name), false, kill_at >= 0 ? 2 : 0);
  const fs::path job = make_job(room.root() / "jobs");
  room.start();
  EXPECT_TRUE(room.submit(job)) << name << ": printd did not take the job";
  if (kill_at >= 0) {
    EXPECT_TRUE(room.wait_printed(kill_at)) << name << ": the printer never printed " << kill_at << " swaths";
    if (kill_printsim) {
      room.kill_printsim();
      room.start();
    } else {
      room.kill_printd();
    }
  }
  const std::string end = room.wait_end();
  room.stop();  // printsim writes the fabric when the job ends, then exits once the writer is done
  Outcome o = collect(room);
  o.state = end;
  return o;
}

TEST(KillResume, TheFabricAfterKillsEqualsACleanRunDropForDrop) {
  const Outcome clean = print_with_kill("clean", -1, false);
  ASSERT_EQ(clean.state, "done");
  ASSERT_FALSE(clean.pixels.empty()) << "no fabric from the clean run";
  const int swaths = static_cast<int>(clean.swaths_printed);
  ASSERT_GE(swaths, 9);
  std::printf("ink drops/fabric-level-sum per ink (cyan magenta yellow black)\n%s\n", row("clean", clean).c_str());
  struct Kill {
    std::string name;
    int at;
    bool printsim;
  };
  // After swaths 1, 3, 5 and 7 are printed, during the last, and printsim itself mid-job.
  const std::vector<Kill> kills = {{"printd-after-1", 2, false}, {"printd-after-3", 4, false},
                                   {"printd-after-5", 6, false}, {"printd-after-7", 8, false},
                                   {"printd-last", swaths - 1, false}, {"printsim-after-4", 5, true}};
  for (const Kill& k : kills) {
    const Outcome o = print_with_kill(k.name, k.at, k.printsim);
    std::printf("%s\n", row(k.name, o).c_str());
    EXPECT_EQ(o.state, "done") << k.name;
    EXPECT_EQ(o.swaths_printed, clean.swaths_printed) << k.name << ": a swath missing or printed twice";
    EXPECT_EQ(o.marker_mm, clean.marker_mm) << k.name << ": the resumed run planned another marker";
    EXPECT_EQ(o.drops, clean.drops) << k.name << ": drops per ink differ from the clean run";
    EXPECT_EQ(o.fabric_sum, clean.fabric_sum) << k.name << ": fabric differs (a swath missing or doubled)";
    EXPECT_TRUE(o.width == clean.width && o.height == clean.height && o.pixels == clean.pixels)
        << k.name << ": the fabric is not the clean run's pixel for pixel";
  }
}

// The HTTP ports printd logged, one per start, oldest first.
std::vector<int> http_ports(const PrintRoom& room) {
  std::vector<int> ports;
  const std::string log = read_text(room.root() / "printd.log");
  const std::regex re(R"(HTTP API on http://127\.0\.0\.1:(\d+))");
  for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
    ports.push_back(std::stoi((*it)[1]));
  return ports;
}

json get_job(int port, std::int64_t id) {
  httplib::Client c("127.0.0.1", port);
  c.set_connection_timeout(1, 0);
  auto r = c.Get("/api/v1/jobs/" + std::to_string(id));
  if (!r || r->status != 200) return json();
  json j = json::parse(r->body, nullptr, false);
  return j.is_discarded() ? json() : j["job"];
}

// Crash safety through the API: the job goes in over HTTP, printd is killed with SIGKILL after the
// printer printed 5 swaths, the service loop starts it again, and GET /api/v1/jobs/{id} on the new
// daemon shows the job resumed (an unclean exit counted, the checkpoint kept) and then done, with
// the clean run's fabric. Prints the time from the kill to the next swath on the fabric.
TEST(KillResume, KilledWhilePrintingTheHttpApiShowsTheJobResumedWithTheCleanFabric) {
  const Outcome clean = print_with_kill("http-clean", -1, false);
  ASSERT_EQ(clean.state, "done");
  ASSERT_FALSE(clean.pixels.empty());

  PrintRoom room(scratch_dir("kill-resume-http"));
  const fs::path job = make_job(room.root() / "jobs");
  room.start();
  std::vector<int> ports;
  for (int i = 0; i < 200 && ports.empty(); ++i) {
    std::this_thread::sleep_for(50ms);
    ports = http_ports(room);
  }
  ASSERT_FALSE(ports.empty()) << read_text(room.root() / "printd.log");
  httplib::MultipartFormDataItems files;
  for (const auto& e : fs::directory_iterator(job))
    files.push_back({"files", read_text(e.path()), e.path().filename().string(), "application/json"});
  httplib::Client c("127.0.0.1", ports.back());
  auto up = c.Post("/api/v1/jobs", files);
  ASSERT_TRUE(up);
  ASSERT_EQ(up->status, 201) << up->body;
  const std::int64_t id = json::parse(up->body)["id"];

  ASSERT_TRUE(room.wait_printed(5)) << "the printer never printed 5 swaths";
  const int printed_at_kill = room.printed_next();
  const auto killed = Clock::now();
  room.kill_printd();
  // The loop starts printd again; its API answers on a new port.
  const auto until = Clock::now() + 60s;
  json resumed;
  while (Clock::now() < until) {
    const std::vector<int> now = http_ports(room);
    if (now.size() > ports.size()) {
      resumed = get_job(now.back(), id);
      if (resumed.is_object() && resumed.value("unclean_exits", 0) == 1) break;
    }
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(resumed.is_object()) << "printd did not come back: " << read_text(room.root() / "printd.log");
  EXPECT_EQ(resumed.value("unclean_exits", 0), 1) << resumed.dump();
  EXPECT_GE(resumed.value("last_acked_swath", -1), 0) << "the checkpoint was lost: " << resumed.dump();
  EXPECT_TRUE(resumed["state"] == "queued" || resumed["state"] == "running" || resumed["state"] == "done")
      << resumed.dump();
  ASSERT_TRUE(room.wait_printed(printed_at_kill + 1, 120s)) << "printing did not go on after the restart";
  std::printf("kill -9 to the next swath on the fabric: %.2f s (swaths printed at the kill: %d)\n",
              std::chrono::duration<double>(Clock::now() - killed).count(), printed_at_kill);

  json end;
  const std::vector<int> now = http_ports(room);
  for (int i = 0; i < 1200; ++i) {
    end = get_job(now.back(), id);
    if (end.is_object() && (end["state"] == "done" || end["state"] == "failed")) break;
    std::this_thread::sleep_for(250ms);
  }
  ASSERT_EQ(end.value("state", ""), "done") << end.dump();
  room.stop();
  const Outcome o = collect(room);
  std::printf("%s\n%s\n", row("http-clean", clean).c_str(), row("http-killed", o).c_str());
  EXPECT_EQ(o.swaths_printed, clean.swaths_printed) << "a swath missing or printed twice";
  EXPECT_EQ(o.drops, clean.drops);
  EXPECT_TRUE(o.width == clean.width && o.height == clean.height && o.pixels == clean.pixels)
      << "the fabric is not the clean run's pixel for pixel";
}

// The same kills with a synthetic job (no planning, so every run sends the same swaths): the
// fabric must equal the clean run's exactly.
Outcome synthetic_with_kill(const std::string& name, int kill_at, bool kill_printsim) {
  PrintRoom room(scratch_dir("kill-synthetic-" + name), true);
  room.start();
  if (kill_at >= 0) {
    EXPECT_TRUE(room.wait_printed(kill_at, 60s)) << name << ": the printer never printed " << kill_at << " swaths";
    if (kill_printsim) {
      room.kill_printsim();
      room.start();
    } else {
      room.kill_printd();
    }
  }
  room.wait_exit();
  Outcome o = collect(room, true);
  const json result = read_json_or_null(room.root() / "result.json");
  o.state = result.is_object() && result.value("error", "").empty() && fs::exists(room.root() / "result.json") ? "done" : "failed";
  return o;
}

TEST(KillResume, ASyntheticJobKilledAtFivePointsAndPowerLostEqualsItsCleanRun) {
  const Outcome clean = synthetic_with_kill("clean", -1, false);
  ASSERT_EQ(clean.state, "done");
  ASSERT_EQ(clean.swaths_printed, 9u);
  ASSERT_FALSE(clean.pixels.empty());
  std::printf("ink drops/fabric-level-sum per ink\n%s\n", row("clean", clean).c_str());
  struct Kill {
    std::string name;
    int at;
    bool printsim;
  };
  const std::vector<Kill> kills = {{"host-after-1", 2, false}, {"host-after-3", 4, false}, {"host-after-5", 6, false},
                                   {"host-after-7", 8, false}, {"host-last", 9, false},    {"printsim-after-4", 5, true}};
  for (const Kill& k : kills) {
    const Outcome o = synthetic_with_kill(k.name, k.at, k.printsim);
    std::printf("%s\n", row(k.name, o).c_str());
    EXPECT_EQ(o.state, "done") << k.name;
    EXPECT_EQ(o.swaths_printed, clean.swaths_printed) << k.name;
    EXPECT_EQ(o.drops, clean.drops) << k.name << ": drops per ink differ from the clean run";
    EXPECT_EQ(o.fabric_sum, clean.fabric_sum) << k.name;
    EXPECT_TRUE(o.width == clean.width && o.height == clean.height && o.pixels == clean.pixels)
        << k.name << ": the fabric is not the clean run's pixel for pixel";
  }
}

}  // namespace
}  // namespace tp::test
