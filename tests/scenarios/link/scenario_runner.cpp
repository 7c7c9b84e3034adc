// tests/scenarios/link/scenario_runner.cpp: runs one printer-link fault scenario end to end and
// judges it. `--baseline` prints the synthetic job without faults; `--scenario f.json` prints it
// under the scenario's faults through `printctl link-job` (real session, libusb and libgpiod code
// under printsim) and checks what the scenario's "expect" asks:
//   outcome "identical": the job succeeded; the fabric equals the baseline's pixel for pixel;
//     every swath was printed exactly once, in order; every cue fired on its GPIO line within
//     one feed step after its position; and the fault really happened (counters in "expect").
//   outcome "error": the job failed with a message containing "error_contains"; the printer's
//     swath log has no swath twice and no gap; the host's message reports no more printed
//     swaths than the printer printed.
#include <OpenImageIO/imageio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The synthetic job every scenario prints: 16 swaths of 128 rows, cues every 4 swaths.
const std::vector<std::string> kJob = {"--swaths", "16", "--rows", "128", "--width", "600", "--cue-every", "4"};
constexpr int kSwaths = 16;
constexpr int kRows = 128;
constexpr int kDpi = 600;

std::int64_t position_um(int swath) { return std::llround(swath * kRows * 25400.0 / kDpi); }

int run(const std::vector<std::string>& cmd) {
  std::vector<char*> argv;
  std::vector<std::string> copy = cmd;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    execv(argv[0], argv.data());
    std::perror("execv");
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

json load(const fs::path& p) {
  std::ifstream in(p);
  if (!in) return json();
  try {
    return json::parse(in);
  } catch (...) {
    return json();
  }
}

bool read_pixels(const fs::path& p, std::vector<std::uint8_t>& px, OIIO::ImageSpec& spec) {
  OIIO::ImageSpec raw_config;
  raw_config.attribute("oiio:RawColor", 1);  // CMYK files: the ink samples, not RGB
  auto in = OIIO::ImageInput::open(p.string(), &raw_config);
  if (!in) return false;
  spec = in->spec();
  px.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  return in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data());
}

struct Judge {
  std::vector<std::string> failures;
  void check(bool ok, const std::string& what) {
    if (!ok) failures.push_back(what);
  }
};

// The printer's swath log: indices of swath_printed events in order.
std::vector<int> printed_log(const json& printer) {
  std::vector<int> v;
  if (printer.contains("events"))
    for (const auto& e : printer["events"])
      if (e.value("kind", "") == "swath_printed") v.push_back(e.value("swath", -1));
  return v;
}

void check_swath_log(Judge& j, const json& printer, int expect_count) {
  const auto log = printed_log(printer);
  bool in_order = true;
  for (std::size_t i = 0; i < log.size(); ++i) in_order &= log[i] == static_cast<int>(i);
  j.check(in_order, "printer's swath log is not 0,1,2,... without repeats or gaps");
  const int counted = printer.contains("counters") ? printer["counters"].value("swaths_printed", -1) : -1;
  j.check(counted == static_cast<int>(log.size()), "printer counted " + std::to_string(counted) +
                                                       " swaths but logged " + std::to_string(log.size()));
  if (expect_count >= 0)
    j.check(static_cast<int>(log.size()) == expect_count,
            "printed " + std::to_string(log.size()) + " swaths, expected " + std::to_string(expect_count));
}

// Every cue fired, at the right place, on the right GPIO line.
void check_cues(Judge& j, const json& result, const json& printer) {
  const std::int64_t step = position_um(1);
  std::vector<std::int64_t> cut_pos, notch_pos, cut_edges, notch_edges;
  for (const auto& c : result.value("cues", json::array())) {
    const std::int64_t pos = c.value("position_um", 0ll), at = c.value("fired_at_um", 0ll);
    const std::string what = "cue " + std::to_string(c.value("id", 0));
    j.check(c.value("fired", false), what + " did not fire");
    j.check(at >= pos && at - pos < step, what + " fired at " + std::to_string(at) + " um, position " +
                                              std::to_string(pos) + " um (feed step " + std::to_string(step) + ")");
    (c.value("kind", "") == "cut" ? cut_pos : notch_pos).push_back(pos);
  }
  for (const auto& e : printer.value("gpio_edges", json::array()))
    if (e.value("level", 0) == 1) {
      const std::string line = e.value("line", "");
      if (line == "cutter-cue") cut_edges.push_back(e.value("fabric_um", 0ll));
      if (line == "notch-mark") notch_edges.push_back(e.value("fabric_um", 0ll));
    }
  for (auto [pos, edges, name] : {std::tuple{&cut_pos, &cut_edges, "cutter-cue"},
                                  std::tuple{&notch_pos, &notch_edges, "notch-mark"}}) {
    j.check(pos->size() == edges->size(), std::string(name) + ": " + std::to_string(edges->size()) +
                                              " rising edges for " + std::to_string(pos->size()) + " cues");
    for (std::size_t i = 0; i < std::min(pos->size(), edges->size()); ++i)
      j.check((*edges)[i] >= (*pos)[i] && (*edges)[i] - (*pos)[i] < step,
              std::string(name) + " edge " + std::to_string(i) + " at " + std::to_string((*edges)[i]) +
                  " um for a cue at " + std::to_string((*pos)[i]) + " um");
  }
  j.check(!cut_pos.empty(), "the job had no cut cues to check");
}

void check_minimums(Judge& j, const json& expect, const json& result, const json& printer, const json& sim) {
  auto at_least = [&](const char* key, double have) {
    if (expect.contains(key))
      j.check(have >= expect[key].get<double>(),
              std::string(key) + ": got " + std::to_string(have) + ", expected at least " + expect[key].dump());
  };
  const json session = result.value("session", json::object());
  const json link = result.value("link", json::object());
  at_least("min_reconnects", session.value("reconnects", 0.0));
  at_least("min_pause_s", session.value("pause_s", 0.0));
  at_least("min_frames_resent", link.value("frames_resent", 0.0));
  at_least("min_naks", link.value("naks_seen", 0.0));
  at_least("min_usb_stalls", sim.contains("usb") ? sim["usb"].value("stalls", 0.0) : 0.0);
  at_least("min_faults_injected", static_cast<double>(printer.value("faults_injected", json::array()).size()));
}

}  // namespace

int main(int argc, char** argv) {
  fs::path bin, work, scenario;
  bool baseline = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--bin" && i + 1 < argc) bin = argv[++i];
    else if (a == "--work" && i + 1 < argc) work = argv[++i];
    else if (a == "--scenario" && i + 1 < argc) scenario = argv[++i];
    else if (a == "--baseline") baseline = true;
  }
  if (bin.empty() || work.empty() || (!baseline && scenario.empty())) {
    std::fprintf(stderr, "usage: %s --bin DIR --work DIR (--baseline | --scenario FILE)\n", argv[0]);
    return 2;
  }
  const std::string name = baseline ? "baseline" : scenario.stem().string();
  const fs::path out = work / name;
  fs::remove_all(out);
  fs::create_directories(out);
  json spec = baseline ? json::object() : load(scenario);
  if (spec.is_null()) {
    std::fprintf(stderr, "%s: cannot read scenario\n", scenario.c_str());
    return 2;
  }
  std::vector<std::string> cmd{(bin / "printctl").string(), "link-job"};
  cmd.insert(cmd.end(), kJob.begin(), kJob.end());
  cmd.insert(cmd.end(), {"--name", name, "--out", out.string(), "--result", (out / "result.json").string()});
  if (!baseline) cmd.insert(cmd.end(), {"--scenario", scenario.string()});
  const json job = spec.value("job", json::object());
  if (job.contains("cutter_timeout_ms")) cmd.insert(cmd.end(), {"--cutter-timeout-ms", job["cutter_timeout_ms"].dump()});
  if (job.contains("reconnect_timeout_ms"))
    cmd.insert(cmd.end(), {"--reconnect-timeout-ms", job["reconnect_timeout_ms"].dump()});
  const int rc = run(cmd);
  const json result = load(out / "result.json"), printer = load(out / "printer.json"), sim = load(out / "printsim.json");
  const json expect = spec.value("expect", json{{"outcome", "identical"}});
  Judge j;
  j.check(!result.is_null(), "no result.json from printctl link-job");
  j.check(!printer.is_null(), "no printer.json from printsim");
  if (expect.value("outcome", "identical") == "identical") {
    j.check(rc == 0, "printctl link-job exited " + std::to_string(rc) + ": " + result.value("error", ""));
    check_swath_log(j, printer, kSwaths);
    check_cues(j, result, printer);
    j.check(printer.value("job", json::object()).value("outcome", "") == "completed", "printer did not complete the job");
    j.check(printer.value("counters", json::object()).value("overruns", 1) == 0, "the host overran the swath buffer");
    if (!baseline) {
      std::vector<std::uint8_t> a, b;
      OIIO::ImageSpec sa, sb;
      const bool ra = read_pixels(work / "baseline" / "fabric.tif", a, sa), rb = read_pixels(out / "fabric.tif", b, sb);
      j.check(ra && rb, "cannot read the baseline's or this run's fabric.tif");
      if (ra && rb) {
        j.check(sa.width == sb.width && sa.height == sb.height, "fabric size differs from the baseline");
        std::size_t diff = 0;
        for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) diff += a[i] != b[i];
        j.check(a.size() == b.size() && diff == 0,
                "fabric differs from the baseline in " + std::to_string(diff) + " samples");
      }
    }
  } else {
    const std::string err = result.value("error", "");
    j.check(rc != 0, "printctl link-job succeeded; expected an error");
    const std::string want = expect.value("error_contains", "");
    j.check(err.find(want) != std::string::npos, "error '" + err + "' lacks '" + want + "'");
    check_swath_log(j, printer, -1);
    const std::string outcome = printer.value("job", json::object()).value("outcome", "");
    j.check(outcome == "failed" || outcome == "aborted" || outcome == "incomplete",
            "printer's job outcome '" + outcome + "' for a failed job");
    std::smatch m;
    const bool named = std::regex_search(err, m, std::regex("below ([0-9]+) printed"));
    j.check(named, "the error does not say how much was printed");
    if (named) {
      const int host = std::stoi(m[1]);
      const int printed = static_cast<int>(printed_log(printer).size());
      j.check(host <= printed, "host reported " + std::to_string(host) + " printed, printer logged " +
                                   std::to_string(printed));
      if (expect.value("exact_printed_report", false))
        j.check(host == printed, "host reported " + std::to_string(host) + " printed, printer logged " +
                                     std::to_string(printed));
    }
  }
  check_minimums(j, expect, result, printer, sim);
  if (j.failures.empty()) {
    std::printf("PASS link/%s\n", name.c_str());
    return 0;
  }
  for (const auto& f : j.failures) std::printf("FAIL link/%s: %s\n", name.c_str(), f.c_str());
  return 1;
}
