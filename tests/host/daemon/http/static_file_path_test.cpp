// tests/host/daemon/http/static_file_path_test.cpp: the console's vendor files: links that stay
// inside the library's folder are followed, names and links that leave it are refused.
#include "host/daemon/http/static_file_path.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

TEST(VendorFilePath, FollowsLinksThatStayInsideTheLibrary) {
  const fs::path lib = tp::test::scratch_dir("http-vendor") / "three";
  fs::create_directories(lib / "build");
  std::ofstream(lib / "three.module.js") << "export {};";
  fs::create_symlink("../three.module.js", lib / "build" / "three.module.js");  // as Debian's libjs-three
  auto r = vendor_file_path(lib, "build/three.module.js");
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(*r, fs::canonical(lib / "three.module.js"));
}

TEST(VendorFilePath, RefusesNamesAndLinksThatLeaveIt) {
  const fs::path root = tp::test::scratch_dir("http-vendor-bad");
  const fs::path lib = root / "three";
  fs::create_directories(lib / "build");
  std::ofstream(root / "secret.txt") << "secret";
  fs::create_symlink(root / "secret.txt", lib / "build" / "out.js");
  for (const char* name : {"../secret.txt", "build/../../secret.txt", "/etc/passwd", "build//out.js", ""}) {
    auto r = vendor_file_path(lib, name);
    ASSERT_FALSE(r) << name;
    EXPECT_EQ(r.error().code, ErrorCode::kUnsafePath) << name;
  }
  auto out = vendor_file_path(lib, "build/out.js");
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().code, ErrorCode::kUnsafePath);
  EXPECT_NE(out.error().message.find("a link leads out"), std::string::npos) << out.error().message;
  // Missing files and folders are "not found", not unsafe.
  EXPECT_EQ(vendor_file_path(lib, "nope.js").error().code, ErrorCode::kJob);
  EXPECT_EQ(vendor_file_path(lib, "build").error().code, ErrorCode::kJob);
}

}  // namespace
}  // namespace tp::host
