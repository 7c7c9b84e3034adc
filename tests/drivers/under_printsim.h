// tests/drivers/under_printsim.h: driver tests talk to the emulated printer and cutting table,
// so they must run under printsim's umockdev preload. A test calls rerun_under_printsim(): in
// the plain test process it runs this same test again under printsim (and checks it passed);
// under printsim it returns true and the test body runs against the emulated hardware.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "host/session/sim_reexec.h"
#include "tests/support/paths.h"

namespace tp::test {

/// True: run the test body now (we are under printsim). False: the body ran in a printsim child
/// whose exit status was checked; `out` (if given) receives printsim's output folder.
inline bool rerun_under_printsim(const std::vector<std::string>& printsim_args = {},
                                 std::filesystem::path* out = nullptr) {
  if (host::under_printsim()) return true;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = std::string(info->test_suite_name()) + "." + info->name();
  const auto dir = scratch_dir("printsim-" + name);
  if (out) *out = dir;
  const std::string printsim = (bin_dir() / "printsim").string();
  if (!std::filesystem::exists(printsim)) {
    ADD_FAILURE() << printsim << " not built: build the printsim target";
    return false;
  }
  std::vector<std::string> cmd{printsim, "run", "--out", dir.string()};
  cmd.insert(cmd.end(), printsim_args.begin(), printsim_args.end());
  // This test binary by its real path: "/proc/self/exe" would name printsim in the child.
  cmd.insert(cmd.end(), {"--", std::filesystem::read_symlink("/proc/self/exe").string(), "--gtest_filter=" + name});
  std::vector<char*> argv;
  for (auto& a : cmd) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << name << " failed under printsim (status " << status << "); its output is above";
  return false;
}

}  // namespace tp::test
