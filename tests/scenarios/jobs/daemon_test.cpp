// tests/scenarios/jobs/daemon_test.cpp: printd as a print room runs it: jobs submitted over the
// socket survive a restart of the daemon, the hot folder files good jobs under done/ and refused
// ones under failed/ with the error, and a queued job can be cancelled. Jobs run without a
// printer (--printer none): the RIP runs in full and its swaths are counted.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

class Printd {
 public:
  explicit Printd(const fs::path& root) : root_(root) {}
  ~Printd() { stop(); }

  void start() {
    pid_ = ::fork();
    if (pid_ == 0) {
      const std::string bin = (bin_dir() / "printd").string(), log = (root_ / "printd.log").string();
      std::FILE* f = std::freopen(log.c_str(), "a", stdout);
      if (f) ::dup2(::fileno(stdout), 2);
      const std::string state = (root_ / "state").string(), hot = (root_ / "hot").string(), out = (root_ / "out").string();
      ::execl(bin.c_str(), bin.c_str(), "--state-dir", state.c_str(), "--hot-folder", hot.c_str(), "--out", out.c_str(),
              "--printer", "none", "--poll-ms", "100", "--listen", "127.0.0.1:0", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    for (int i = 0; i < 200; ++i) {
      if (ctl({"status"}).exit_code == 0) return;
      std::this_thread::sleep_for(50ms);
    }
    ADD_FAILURE() << "printd did not answer on its socket";
  }

  /// SIGTERM and wait; returns the exit status.
  int stop() {
    if (pid_ <= 0) return -1;
    ::kill(pid_, SIGTERM);
    int st = 0;
    ::waitpid(pid_, &st, 0);
    pid_ = -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  }

  CommandResult ctl(std::vector<std::string> args) const {
    args.insert(args.begin(), (bin_dir() / "printctl").string());
    args.push_back("--state-dir");
    args.push_back((root_ / "state").string());
    return run_command(args);
  }

  json jobs() const {
    auto r = ctl({"status", "--json"});
    if (r.exit_code != 0) return json::array();
    return json::parse(r.output)["jobs"];
  }

  std::string state_of(const std::string& name) const {
    for (const json& j : jobs())
      if (j["name"] == name) return j["state"];
    return "";
  }

  /// Waits until the job has ended (done, failed or cancelled), at most `limit`.
  std::string wait_end(const std::string& name, std::chrono::seconds limit = 180s) const {
    const auto until = std::chrono::steady_clock::now() + limit;
    std::string s;
    while (std::chrono::steady_clock::now() < until) {
      s = state_of(name);
      if (s == "done" || s == "failed" || s == "cancelled") return s;
      std::this_thread::sleep_for(200ms);
    }
    return s;
  }

 private:
  fs::path root_;
  pid_t pid_ = -1;
};

// A copy of the flat example under another name (outputs go to out/<name>/).
fs::path job_named(const fs::path& dir, const std::string& name) {
  const fs::path job = dir / name;
  fs::create_directories(dir);
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  json j = read_json(job / "job.json");
  j["name"] = name;
  j["marker"]["time_limit_s"] = 1;
  std::ofstream(job / "job.json") << j.dump(2);
  return job;
}

bool wait_for(const fs::path& p, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    if (fs::exists(p)) return true;
    std::this_thread::sleep_for(100ms);
  }
  return false;
}

TEST(Daemon, SubmittedJobsSurviveARestart) {
  const fs::path root = scratch_dir("daemon-restart");
  const fs::path a = job_named(root / "jobs", "first"), b = job_named(root / "jobs", "second");
  Printd d(root);
  d.start();
  auto sa = d.ctl({"submit", a.string()});
  ASSERT_EQ(sa.exit_code, 0) << sa.output;
  auto sb = d.ctl({"submit", b.string()});
  ASSERT_EQ(sb.exit_code, 0) << sb.output;
  // Stop while the first job runs and the second waits: both are in the database. A job takes
  // seconds and the second was submitted right after the first, so it has not started; the
  // first may be running (then it is resumed) or, on a fast machine, done.
  const std::string second_before = d.state_of("second");
  ASSERT_EQ(second_before, "queued") << "the second job must still wait when the daemon stops";
  EXPECT_EQ(d.stop(), 0);
  // The submitted packages were spooled: the originals may go away.
  fs::remove_all(root / "jobs");
  d.start();
  EXPECT_EQ(d.wait_end("first"), "done");
  EXPECT_EQ(d.wait_end("second"), "done");
  const json rep = read_json(root / "out/second/report.json");
  EXPECT_EQ(rep["state"], "done");
  EXPECT_GT(rep["print"]["swaths_total"].get<int>(), 0);
  EXPECT_EQ(rep["print"]["printer"], "none");
}

TEST(Daemon, TheHotFolderFilesGoodJobsUnderDoneAndRefusedOnesUnderFailed) {
  const fs::path root = scratch_dir("daemon-hot");
  fs::create_directories(root / "hot");
  Printd d(root);
  d.start();
  // Built beside the hot folder, then moved in whole, as a print-room tool would.
  const fs::path good = job_named(root / "staging", "hot-good");
  const fs::path bad = job_named(root / "staging", "hot-bad");
  {
    json j = read_json(bad / "job.json");
    j["marker"]["fabric_width"] = "wide";
    std::ofstream(bad / "job.json") << j.dump(2);
  }
  fs::rename(bad, root / "hot/hot-bad");
  fs::rename(good, root / "hot/hot-good");
  ASSERT_TRUE(wait_for(root / "hot/failed/hot-bad/error.txt", 30s));
  const std::string message = read_text(root / "hot/failed/hot-bad/error.txt");
  EXPECT_NE(message.find("/marker/fabric_width"), std::string::npos) << message;
  ASSERT_TRUE(wait_for(root / "hot/done/hot-good/report.json", 180s)) << d.state_of("hot-good");
  EXPECT_FALSE(fs::exists(root / "hot/hot-good"));
  EXPECT_EQ(d.state_of("hot-good"), "done");
}

TEST(Daemon, AQueuedJobCanBeCancelled) {
  const fs::path root = scratch_dir("daemon-cancel");
  const fs::path a = job_named(root / "jobs", "runs"), b = job_named(root / "jobs", "cancelled");
  Printd d(root);
  d.start();
  ASSERT_EQ(d.ctl({"submit", a.string()}).exit_code, 0);
  auto sb = d.ctl({"submit", b.string()});
  ASSERT_EQ(sb.exit_code, 0) << sb.output;
  std::int64_t id = 0;
  for (const json& j : d.jobs())
    if (j["name"] == "cancelled") id = j["id"];
  ASSERT_GT(id, 0);
  auto c = d.ctl({"cancel", std::to_string(id)});
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_EQ(d.wait_end("cancelled"), "cancelled");
  EXPECT_EQ(d.wait_end("runs"), "done");
  EXPECT_FALSE(fs::exists(root / "out/cancelled/fabric.png"));
  // Asking about or cancelling a job that does not exist is an error, not a crash.
  EXPECT_NE(d.ctl({"cancel", "9999"}).exit_code, 0);
  EXPECT_NE(d.ctl({"status", "9999"}).exit_code, 0);
}

}  // namespace
}  // namespace tp::test
