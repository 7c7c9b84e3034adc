// tests/host/job/package_test.cpp: zip packages unpack safely: no escapes, links or bombs.
#include "host/job/package.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zip.h>

#include <fstream>
#include <string>
#include <vector>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

struct Entry {
  std::string name;
  std::string data;
  bool symlink = false;
  zip_uint32_t unix_mode = 0;  ///< written as the entry's Unix mode when non-zero
};

// Writes a zip with libzip (entries stored deflated).
fs::path make_zip(const fs::path& dir, const std::vector<Entry>& entries) {
  fs::path p = dir / "job.zip";
  int err = 0;
  zip_t* z = zip_open(p.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  EXPECT_NE(z, nullptr);
  for (const auto& e : entries) {
    zip_source_t* src = zip_source_buffer(z, e.data.data(), e.data.size(), 0);
    zip_int64_t idx = zip_file_add(z, e.name.c_str(), src, ZIP_FL_OVERWRITE);
    EXPECT_GE(idx, 0) << e.name;
    if (e.symlink)
      zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(idx), 0, ZIP_OPSYS_UNIX,
                                       static_cast<zip_uint32_t>(S_IFLNK | 0777) << 16);
    if (e.unix_mode)
      zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(idx), 0, ZIP_OPSYS_UNIX, e.unix_mode << 16);
  }
  EXPECT_EQ(zip_close(z), 0);
  return p;
}

TEST(JobPackage, ZipUnpacksAndFindsManifestInTopFolder) {
  fs::path dir = tp::test::scratch_dir("pkg-ok");
  fs::path zip = make_zip(dir, {{"myjob/job.json", "{}"}, {"myjob/pattern.json", "{}"}});
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_TRUE(pkg) << pkg.error().message;
  EXPECT_TRUE(fs::exists(pkg->root() / "pattern.json"));
  auto asset = pkg->resolve_asset("pattern.json", "/garment/pattern");
  ASSERT_TRUE(asset) << asset.error().message;
}

TEST(JobPackage, ZipEntryEscapingPackageIsRefused) {
  fs::path dir = tp::test::scratch_dir("pkg-escape");
  fs::path zip = make_zip(dir, {{"job.json", "{}"}, {"../evil.txt", "x"}});
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_EQ(pkg.error().code, ErrorCode::kUnsafePath);
  EXPECT_NE(pkg.error().message.find("entry \"../evil.txt\""), std::string::npos) << pkg.error().message;
  EXPECT_FALSE(fs::exists(dir / "evil.txt"));
}

TEST(JobPackage, ZipAbsoluteEntryIsRefused) {
  fs::path dir = tp::test::scratch_dir("pkg-abs");
  fs::path zip = make_zip(dir, {{"job.json", "{}"}, {"/tmp/evil.txt", "x"}});
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_EQ(pkg.error().code, ErrorCode::kUnsafePath) << pkg.error().message;
}

TEST(JobPackage, ZipSymlinkEntryIsRefused) {
  fs::path dir = tp::test::scratch_dir("pkg-link");
  fs::path zip = make_zip(dir, {{"job.json", "{}"}, {"pattern.json", "/etc/passwd", true}});
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_NE(pkg.error().message.find("symbolic link"), std::string::npos) << pkg.error().message;
}

TEST(JobPackage, DecompressionBombIsStoppedByRatio) {
  fs::path dir = tp::test::scratch_dir("pkg-bomb");
  std::string zeros(32u << 20, '\0');
  fs::path zip = make_zip(dir, {{"job.json", "{}"}, {"bomb.bin", zeros}});
  ASSERT_LT(fs::file_size(zip), 1u << 20);
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_EQ(pkg.error().code, ErrorCode::kArchive);
  EXPECT_NE(pkg.error().message.find("compression ratio"), std::string::npos) << pkg.error().message;
}

TEST(JobPackage, SizeLimitHoldsOnInflatedBytes) {
  fs::path dir = tp::test::scratch_dir("pkg-size");
  std::string data(3u << 20, 'a');
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>('a' + (i * 7919) % 26);
  fs::path zip = make_zip(dir, {{"job.json", "{}"}, {"big.bin", data}});
  PackageLimits limits;
  limits.max_entry_bytes = 1u << 20;
  auto pkg = JobPackage::open(zip, dir / "unpacked", limits);
  ASSERT_FALSE(pkg);
  EXPECT_NE(pkg.error().message.find("per-file limit"), std::string::npos) << pkg.error().message;
}

TEST(JobPackage, NotAZipIsReported) {
  fs::path dir = tp::test::scratch_dir("pkg-notzip");
  std::ofstream(dir / "job.zip") << "this is not a zip";
  auto pkg = JobPackage::open(dir / "job.zip", dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_NE(pkg.error().message.find("job.zip: not a readable zip archive"), std::string::npos)
      << pkg.error().message;
}

TEST(JobPackage, FolderWithoutManifestIsReported) {
  fs::path dir = tp::test::scratch_dir("pkg-nomanifest");
  auto pkg = JobPackage::open(dir, dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_NE(pkg.error().message.find("job.json is missing"), std::string::npos);
}

TEST(CheckRelativePath, RefusesEscapes) {
  EXPECT_TRUE(check_relative_path("images/motif.png"));
  EXPECT_FALSE(check_relative_path(""));
  EXPECT_FALSE(check_relative_path("/abs"));
  EXPECT_FALSE(check_relative_path("a/../../b"));
  EXPECT_FALSE(check_relative_path("a\\b"));
}

TEST(JobPackage, ZipEntryWithPermissionBitsOnlyIsAPlainFile) {
  // Python's zipfile.writestr records 0600 with no file type; such an entry is a plain file.
  fs::path dir = tp::test::scratch_dir("pkg-modebits");
  fs::path zip = make_zip(dir, {{"job.json", "{}", false, 0600}, {"pattern.json", "{}", false, 0644}});
  auto pkg = JobPackage::open(zip, dir / "unpacked");
  ASSERT_TRUE(pkg) << pkg.error().message;
  EXPECT_TRUE(fs::is_regular_file(pkg->root() / "pattern.json"));
  // A device node is still refused.
  fs::path dir2 = tp::test::scratch_dir("pkg-modebits-dev");
  fs::path zip2 = make_zip(dir2, {{"job.json", "{}", false, S_IFCHR | 0600}});
  EXPECT_FALSE(JobPackage::open(zip2, dir2 / "unpacked"));
}

TEST(JobPackage, SymlinkedManifestIsRefused) {
  fs::path dir = tp::test::scratch_dir("pkg-manifest-link");
  fs::create_directories(dir / "job");
  std::ofstream(dir / "outside.json") << "{}";
  fs::create_symlink(dir / "outside.json", dir / "job" / "job.json");
  auto pkg = JobPackage::open(dir / "job", dir / "unpacked");
  ASSERT_FALSE(pkg);
  EXPECT_EQ(pkg.error().code, ErrorCode::kUnsafePath);
  EXPECT_NE(pkg.error().message.find("job.json is a symbolic link"), std::string::npos) << pkg.error().message;
}

TEST(JobPackage, LimitsAreSetByName) {
  PackageLimits l;
  ASSERT_TRUE(set_limit(l, "max_stroke_points=500"));
  EXPECT_EQ(l.max_stroke_points, 500u);
  auto bad = set_limit(l, "max_strokes=5");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("max_stroke_points"), std::string::npos);
  EXPECT_FALSE(set_limit(l, "max_layers=-3"));
  EXPECT_FALSE(set_limit(l, "max_layers"));
}

}  // namespace
}  // namespace tp::host
