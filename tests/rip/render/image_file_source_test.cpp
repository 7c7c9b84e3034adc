// tests/rip/render/image_file_source_test.cpp: an image file streamed into the RIP gives exactly the
// swaths of the same image read whole; decode errors and out-of-window requests stop the job.
#include "rip/render/image_file_source.h"

#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "rip/image/image_io.h"
#include "rip/job/rip_job.h"
#include "rip/render/image_source.h"
#include "tests/support/image_files.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

using geometry::ImageRgba8;

ImageRgba8 pattern(int w, int h) {
  ImageRgba8 img;
  img.width_px = w;
  img.height_px = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.pixels.push_back({static_cast<std::uint8_t>(x * 3 + y), static_cast<std::uint8_t>(255 - y % 200),
                            static_cast<std::uint8_t>((x / 8 + y / 8) % 2 ? 220 : 30), 255});
  return img;
}

std::vector<device::Swath> rip_all(const BandSource& src, Result<RipStats>& stats, int band_rows = 64) {
  device::PrinterModel printer;
  printer.nozzles_per_ink = 64;
  RipSettings s;
  s.band_rows = band_rows;
  s.threads = 2;
  std::vector<device::Swath> out;
  stats = run_rip(src, printer, s, [&](device::Swath&& sw) -> Status {
    out.push_back(std::move(sw));
    return {};
  });
  return out;
}

TEST(ImageFileSource, StreamedRowsAreTheRowsReadWhole) {
  auto dir = test::scratch_dir("image_file_source_rows");
  ASSERT_TRUE(write_png(dir / "p.png", pattern(70, 301)));
  auto whole = read_image(dir / "p.png");
  ASSERT_TRUE(whole);
  auto src = ImageFileSource::open(dir / "p.png", 48);
  ASSERT_TRUE(src) << src.error().what();
  ASSERT_EQ((*src)->width_px(), 70);
  ASSERT_EQ((*src)->height_px(), 301);
  // Two threads take 16-row tiles out of order within each 32-row band, as the RIP's workers do.
  std::vector<geometry::Rgba8> got(70 * 301);
  for (int band = 0; band < 301; band += 32) {
    std::thread later([&] {
      if (band + 16 < 301) (*src)->render_rows(band + 16, 16, got.data() + (band + 16) * 70, 70);
    });
    (*src)->render_rows(band, 16, got.data() + band * 70, 70);
    later.join();
  }
  EXPECT_TRUE((*src)->status());
  EXPECT_EQ(got, whole->pixels);
}

TEST(ImageFileSource, RipOfTheStreamedFileMatchesTheImageInMemory) {
  auto dir = test::scratch_dir("image_file_source_rip");
  ASSERT_TRUE(write_png(dir / "p.png", pattern(200, 500)));
  auto whole = read_image(dir / "p.png");
  ASSERT_TRUE(whole);
  Result<RipStats> a, b;
  auto in_memory = rip_all(ImageSource(*whole), a);
  auto src = ImageFileSource::open(dir / "p.png", 2 * 64);
  ASSERT_TRUE(src);
  auto streamed = rip_all(**src, b);
  ASSERT_TRUE(a && b) << (a ? b.error().what() : a.error().what());
  ASSERT_EQ(in_memory.size(), streamed.size());
  ASSERT_GT(in_memory.size(), 3u);
  for (std::size_t i = 0; i < in_memory.size(); ++i) EXPECT_EQ(in_memory[i].data, streamed[i].data) << i;
  EXPECT_EQ(a->drops, b->drops);
}

TEST(ImageFileSource, AFileCutShortStopsTheRipNamingTheFile) {
  // A PNG's header is intact, so the source opens; decoding fails where the data stops.
  auto dir = test::scratch_dir("image_file_source_cut");
  ASSERT_TRUE(write_png(dir / "full.png", pattern(300, 600)));
  std::ifstream f(dir / "full.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(f)), {});
  std::ofstream(dir / "cut.png", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 3));
  auto src = ImageFileSource::open(dir / "cut.png", 128);
  ASSERT_TRUE(src) << src.error().what();
  Result<RipStats> st;
  rip_all(**src, st);
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("cut.png"), std::string::npos) << st.error().message;
  EXPECT_NE(st.error().message.find("RIP at fabric row"), std::string::npos) << st.error().message;
  // A JPEG cut short would decode to grey rows: it is refused before the RIP starts.
  ASSERT_TRUE(write_jpeg(dir / "full.jpg", pattern(300, 600), 90));
  std::ifstream fj(dir / "full.jpg", std::ios::binary);
  std::string jpeg((std::istreambuf_iterator<char>(fj)), {});
  std::ofstream(dir / "cut.jpg", std::ios::binary).write(jpeg.data(), static_cast<std::streamsize>(jpeg.size() / 3));
  auto cut_jpeg = ImageFileSource::open(dir / "cut.jpg", 128);
  ASSERT_FALSE(cut_jpeg);
  EXPECT_NE(cut_jpeg.error().message.find("cut.jpg: JPEG data ends before"), std::string::npos)
      << cut_jpeg.error().message;
}

TEST(ImageFileSource, ARequestBeyondTheWindowFailsInsteadOfWaiting) {
  auto dir = test::scratch_dir("image_file_source_window");
  ASSERT_TRUE(write_png(dir / "p.png", pattern(20, 400)));
  auto src = ImageFileSource::open(dir / "p.png", 32);
  ASSERT_TRUE(src);
  std::vector<geometry::Rgba8> rows(20 * 16);
  (*src)->render_rows(320, 16, rows.data(), 20);  // rows 0..319 were never taken: out of reach
  auto s = (*src)->status();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("outside the decoded window"), std::string::npos) << s.error().message;
  EXPECT_FALSE(ImageFileSource::open(dir / "p.png", 8));
  EXPECT_FALSE(ImageFileSource::open(dir / "missing.png", 64));
}

TEST(ImageFileSource, AnOrientedImageIsTurnedUpright) {
  auto dir = test::scratch_dir("image_file_source_orient");
  test::write_oriented_tiff(dir / "o.tif");
  auto src = ImageFileSource::open(dir / "o.tif", 32);
  ASSERT_TRUE(src) << src.error().what();
  ASSERT_EQ((*src)->width_px(), 2);
  ASSERT_EQ((*src)->height_px(), 3);
  std::vector<geometry::Rgba8> rows(2 * 3);
  (*src)->render_rows(0, 16, rows.data(), 2);
  EXPECT_EQ(rows[0].r, 30);
  EXPECT_EQ(rows[1].r, 0);
}

}  // namespace
}  // namespace tp::rip
