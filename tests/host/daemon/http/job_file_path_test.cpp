// tests/host/daemon/http/job_file_path_test.cpp: the file route serves the job's own outputs only:
// no "..", no absolute paths, no symlinks anywhere on the way, no folders.
#include "host/daemon/http/job_file_path.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

TEST(JobFilePath, ServesFilesInsideTheOutputFolder) {
  const fs::path out = tp::test::scratch_dir("http-files") / "out";
  fs::create_directories(out / "pieces");
  std::ofstream(out / "report.json") << "{}";
  std::ofstream(out / "pieces" / "front.png") << "png";
  auto r = job_file_path(out, "report.json");
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(*r, out / "report.json");
  auto p = job_file_path(out, "pieces/front.png");
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_EQ(*p, out / "pieces" / "front.png");
}

TEST(JobFilePath, RefusesEverythingThatCouldLeaveIt) {
  const fs::path root = tp::test::scratch_dir("http-files-bad");
  const fs::path out = root / "out";
  fs::create_directories(out / "pieces");
  std::ofstream(root / "secret.txt") << "secret";
  std::ofstream(out / "report.json") << "{}";
  fs::create_symlink(root / "secret.txt", out / "link.txt");
  fs::create_directory_symlink(root, out / "up");
  for (const char* name : {"../secret.txt", "pieces/../../secret.txt", "/etc/passwd", "./report.json", "pieces//x",
                           "link.txt", "up/secret.txt", "pieces\\..\\..\\secret.txt", "", "report.json/"}) {
    auto r = job_file_path(out, name);
    EXPECT_FALSE(r) << name;
    if (!r) {
      EXPECT_NE(r.error().message.find("file '"), std::string::npos) << name;
    }
  }
  EXPECT_EQ(job_file_path(out, "link.txt").error().code, ErrorCode::kUnsafePath);
  EXPECT_EQ(job_file_path(out, "../secret.txt").error().code, ErrorCode::kUnsafePath);
  // Missing files and folders are "not found", not unsafe.
  EXPECT_EQ(job_file_path(out, "nope.png").error().code, ErrorCode::kJob);
  EXPECT_EQ(job_file_path(out, "pieces").error().code, ErrorCode::kJob);
}

}  // namespace
}  // namespace tp::host
