// tests/host/common/atomic_file_test.cpp: outputs appear whole or not at all; a full disk is named.
#include "host/common/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "host/common/failure_report.h"
#include "host/common/sha256.h"
#include "host/common/text.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AtomicFile, FullDiskIsNamedAndTheOldFileStays) {
  fs::path dir = tp::test::scratch_dir("atomic-enospc");
  ASSERT_TRUE(write_file_atomic(dir / "cut.dxf", "old"));
  set_write_budget_for_tests(10);
  auto st = write_file_atomic(dir / "cut.dxf", std::string(1000, 'x'));
  set_write_budget_for_tests(-1);
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find((dir / "cut.dxf").string()), std::string::npos) << st.error().message;
  EXPECT_NE(st.error().message.find("ENOSPC"), std::string::npos) << st.error().message;
  EXPECT_EQ(slurp(dir / "cut.dxf"), "old");
  EXPECT_FALSE(fs::exists(temp_path_for(dir / "cut.dxf")));
}

TEST(AtomicFile, WriterThatLeavesNothingIsAnError) {
  fs::path dir = tp::test::scratch_dir("atomic-empty");
  auto st = write_via_temp(dir / "a.png", [](const fs::path& tmp) -> Status {
    std::ofstream(tmp).flush();  // 0 bytes, no error: what a writer on a full disk did
    return {};
  });
  ASSERT_FALSE(st);
  EXPECT_FALSE(fs::exists(dir / "a.png"));
  // A writer's own error names the real output, not the temporary file.
  auto st2 = write_via_temp(dir / "b.png", [](const fs::path& tmp) -> Status {
    return fail(ErrorCode::kIo, tmp.string() + ": No space left on device");
  });
  ASSERT_FALSE(st2);
  EXPECT_EQ(st2.error().message, (dir / "b.png").string() + ": No space left on device");
}

TEST(AtomicFile, PngOutputIsWrittenThroughItsTemporaryName) {
  fs::path dir = tp::test::scratch_dir("atomic-ext");
  EXPECT_EQ(temp_path_for(dir / "marker.png").extension(), ".png");  // writers choose formats by it
  EXPECT_EQ(temp_path_for(dir / "marker.png").filename().string()[0], '.');
}

TEST(FailureReport, ReservedReportIsRewrittenWithTheError) {
  fs::path dir = tp::test::scratch_dir("report-fallback");
  ASSERT_TRUE(reserve_report(dir, "j", 7));
  EXPECT_EQ(fs::file_size(dir / "report.json"), kReservedReportBytes);
  ASSERT_TRUE(ensure_failure_report(dir, "j", 7, "failed", "out/cut.dxf: No space left on device (ENOSPC)"));
  auto j = nlohmann::json::parse(slurp(dir / "report.json"));
  EXPECT_EQ(j["state"], "failed");
  EXPECT_EQ(j["error"], "out/cut.dxf: No space left on device (ENOSPC)");
  EXPECT_LE(fs::file_size(dir / "report.json"), kReservedReportBytes);
}

TEST(Text, InvalidUtf8IsEscapedNotThrown) {
  const std::string latin1 = "caf\xE9.zip";
  EXPECT_FALSE(is_valid_utf8(latin1));
  EXPECT_EQ(printable_utf8(latin1), "caf\\xE9.zip");
  EXPECT_TRUE(is_valid_utf8("caf\xC3\xA9"));
  EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));  // a surrogate
  nlohmann::json j = {{"name", latin1}};
  EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);
  EXPECT_NO_THROW((void)dump_json(j));
}

TEST(Sha256, KnownDigestsAndPackageHash) {
  Sha256 a;
  EXPECT_EQ(a.hex_digest(), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  Sha256 b;
  b.update("abc");
  EXPECT_EQ(b.hex_digest(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  fs::path d1 = tp::test::scratch_dir("hash-a"), d2 = tp::test::scratch_dir("hash-b");
  for (const auto& d : {d1, d2}) std::ofstream(d / "job.json") << "{}";
  EXPECT_EQ(*package_hash(d1), *package_hash(d2));
  std::ofstream(d2 / "job.json") << "{ }";
  EXPECT_NE(*package_hash(d1), *package_hash(d2));
}

}  // namespace
}  // namespace tp::host
