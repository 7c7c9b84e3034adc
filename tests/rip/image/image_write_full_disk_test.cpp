// tests/rip/image/image_write_full_disk_test.cpp: a PNG that cannot be written whole is an error
// naming the file and ENOSPC, never a silent empty or truncated file.
#include <gtest/gtest.h>

#include <filesystem>

#include "rip/image/image_io.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

TEST(ImageWrite, FullDiskIsReportedWithTheFileAndEnospc) {
  geometry::ImageRgba8 img;
  img.width_px = 64;
  img.height_px = 64;
  img.pixels.assign(64 * 64, geometry::Rgba8{10, 20, 30, 255});
  // Every write(2) to /dev/full fails with ENOSPC, as on a full disk (reached through a .png
  // link, since the writer is chosen by the extension).
  const auto path = tp::test::scratch_dir("png-full-disk") / "full.png";
  std::filesystem::create_symlink("/dev/full", path);
  auto st = write_png(path, img);
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find(path.string()), std::string::npos) << st.error().message;
  EXPECT_NE(st.error().message.find("ENOSPC"), std::string::npos) << st.error().message;
}

}  // namespace
}  // namespace tp::rip
