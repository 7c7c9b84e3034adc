// tests/host/pipeline/determinism_slow_test.cpp: the same job run twice, the second time while
// other processes load every core, gives the same files byte for byte: garment, draped garment
// and its print previews, pieces, marker, cut files and the swath plan (the digest of every swath
// the printer would get).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <thread>
#include <vector>

#include "tests/host/pipeline/plan_job.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// `count` busy processes (`yes > /dev/null`), killed and reaped when this goes out of scope.
class CpuLoad {
 public:
  explicit CpuLoad(int count) {
    for (int i = 0; i < count; ++i) {
      const pid_t pid = fork();
      if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, 1);
        execlp("yes", "yes", static_cast<char*>(nullptr));
        _exit(127);
      }
      if (pid > 0) pids_.push_back(pid);
    }
  }
  ~CpuLoad() {
    for (pid_t pid : pids_) kill(pid, SIGKILL);
    for (pid_t pid : pids_) waitpid(pid, nullptr, 0);
  }
  int running() const { return static_cast<int>(pids_.size()); }

 private:
  std::vector<pid_t> pids_;
};

// Every output file that must repeat, relative to the run's folder (out/ or plan/).
std::vector<std::string> compared_files(const fs::path& run) {
  std::vector<std::string> files = {"out/garment.obj",
                                    "out/garment-draped.obj",
                                    "out/garment-print-front.png",
                                    "out/garment-print-side.png",
                                    "out/garment-print-back.png",
                                    "out/marker.png",
                                    "out/cut.dxf",
                                    "out/cut.svg",
                                    "plan/garment.plan",
                                    "plan/pieces.json",
                                    "plan/marker.json",
                                    "plan/swaths.json"};
  for (const auto& e : fs::directory_iterator(run / "out" / "pieces"))
    files.push_back("out/pieces/" + e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(Determinism, TheSameJobUnderCpuLoadGivesTheSameFilesByteForByte) {
  const fs::path dir = scratch_dir("determinism_load");
  json manifest = plan_job_manifest(75);
  manifest["garment"]["mesh_edge"] = "15 mm";     // the examples' mesh: thousands of vertices
  manifest["marker"]["budget"]["iterations"] = 400;
  const host::Job job = write_plan_job(dir / "job", manifest);

  const json idle = run_plan_job(job, dir / "idle" / "out", dir / "idle" / "plan");
  ASSERT_EQ(idle["state"], "done") << idle.dump(1);
  json loaded;
  {
    // Twice as many busy processes as cores: the pipeline's threads are preempted at random.
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    CpuLoad load(2 * cores);
    ASSERT_EQ(load.running(), 2 * cores);
    loaded = run_plan_job(job, dir / "loaded" / "out", dir / "loaded" / "plan");
  }
  ASSERT_EQ(loaded["state"], "done") << loaded.dump(1);

  const auto files = compared_files(dir / "idle");
  ASSERT_EQ(files, compared_files(dir / "loaded"));
  std::vector<std::string> differ;
  for (const auto& f : files) {
    const std::string a = file_bytes(dir / "idle" / f), b = file_bytes(dir / "loaded" / f);
    EXPECT_FALSE(a.empty()) << f;
    if (a != b) differ.push_back(f);
  }
  EXPECT_TRUE(differ.empty()) << "differ under load: " << json(differ).dump();
  RecordProperty("files_compared", static_cast<int>(files.size()));
  RecordProperty("seconds_idle", std::to_string(idle["wall_s"].get<double>()));
  RecordProperty("seconds_loaded", std::to_string(loaded["wall_s"].get<double>()));
  EXPECT_EQ(idle["garment"]["strain_mean"], loaded["garment"]["strain_mean"]);
  EXPECT_EQ(idle["marker"]["length_mm"], loaded["marker"]["length_mm"]);
  EXPECT_EQ(idle["rip"]["drops_per_ink"], loaded["rip"]["drops_per_ink"]);
}

}  // namespace
}  // namespace tp::test
