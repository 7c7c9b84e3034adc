// tests/rip/job/rip_job_test.cpp: the streaming RIP job end to end on a small fixed marker: golden swaths,
// band/thread independence, multi-pass coverage, resume, cancel, separations and errors.
#include "rip/job/rip_job.h"

#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "host/bench/textured_piece_renderer.h"
#include "rip/image/image_io.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

using geometry::Marker;
using geometry::PiecePlacement;

/// A procedural texture: colour ramps with stripes, varied enough to use every ink and level.
geometry::ImageHandle test_texture() {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = 48;
  img->height_px = 32;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x)
      img->pixels.push_back({static_cast<std::uint8_t>(x * 5), static_cast<std::uint8_t>(255 - y * 7),
                             static_cast<std::uint8_t>((x / 6 + y / 4) % 2 ? 230 : 40), 255});
  return img;
}

/// Three pieces (rectangle, turned rectangle, mirrored triangle) on a 40 x 30 mm marker with a
/// blank gap in the middle of the roll.
struct SmallJob {
  TexturedPieceRenderer renderer{{
      {{{0, 0}, {14, 0}, {14, 9}, {0, 9}}, test_texture(), 4.0, {}},
      {{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, test_texture(), 6.0, {1, 2}},
      {{{0, 0}, {12, 0}, {3, 8}}, test_texture(), 3.0, {}},
  }};
  Marker marker;
  device::PrinterModel printer;
  SmallJob() {
    marker.width_mm = 40;
    marker.length_mm = 30;
    // Offsets allow for the face-up flip (piece y up, roll y down).
    marker.placements = {PiecePlacement{0, 0, false, {2, 10}}, PiecePlacement{1, 90, false, {28, 2}},
                         PiecePlacement{2, 30, true, {25, 20}}};
    printer.nozzles_per_ink = 64;
  }
};

struct Collected {
  std::vector<device::Swath> swaths;
  SwathSink sink() {
    return [this](device::Swath&& s) -> Status {
      swaths.push_back(std::move(s));
      return {};
    };
  }
};

Result<RipStats> run(const SmallJob& job, const RipSettings& s, Collected& out, const ProgressCallback& p = {},
                     const geometry::CancelToken& cancel = {}) {
  return rip_marker(job.marker, job.renderer, job.printer, s, out.sink(), p, cancel);
}

bool same_header(const device::SwathHeader& a, const device::SwathHeader& b) {
  return a.index == b.index && a.pass == b.pass && a.direction == b.direction && a.first_row == b.first_row &&
         a.row_step == b.row_step && a.rows == b.rows && a.x_start_px == b.x_start_px && a.width_px == b.width_px &&
         a.channels == b.channels && a.bits_per_pixel == b.bits_per_pixel && a.feed_before_um == b.feed_before_um &&
         a.compression == b.compression && a.raw_bytes == b.raw_bytes;
}

void expect_same_stream(const std::vector<device::Swath>& a, const std::vector<device::Swath>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_header(a[i].header, b[i].header)) << what << " swath " << i;
    EXPECT_EQ(a[i].data, b[i].data) << what << " swath " << i;
  }
}

/// Lays decoded swaths onto a fabric of codes; counts pixels that received ink twice.
struct Fabric {
  int width, height, channels;
  std::vector<std::uint8_t> codes;  ///< [channel][row][column]
  int doubled = 0;
  Fabric(int w, int h, int c) : width(w), height(h), channels(c), codes(static_cast<size_t>(w) * h * c, 0) {}
  void lay(const device::Swath& s) {
    auto raw = decode_swath_data(s);
    ASSERT_TRUE(raw) << raw.error().what();
    const auto& h = s.header;
    const int rb = static_cast<int>(device::swath_row_bytes(h)), per = 8 / h.bits_per_pixel;
    for (int c = 0; c < h.channels; ++c)
      for (std::uint32_t r = 0; r < h.rows; ++r) {
        const std::int64_t y = h.first_row + static_cast<std::int64_t>(r) * h.row_step;
        ASSERT_GE(y, 0);
        ASSERT_LT(y, height);
        const std::uint8_t* row = raw->data() + (static_cast<size_t>(c) * h.rows + r) * rb;
        for (std::uint32_t i = 0; i < h.width_px; ++i) {
          const int code = (row[i / per] >> (8 - h.bits_per_pixel - (i % per) * h.bits_per_pixel)) & ((1 << h.bits_per_pixel) - 1);
          if (!code) continue;
          auto& cell = codes[(static_cast<size_t>(c) * height + y) * width + h.x_start_px + i];
          if (cell) ++doubled;
          cell = static_cast<std::uint8_t>(code);
        }
      }
  }
};

Fabric lay_all(const std::vector<device::Swath>& swaths, const RipStats& st) {
  Fabric f(st.width_px, static_cast<int>(st.height_px), 4);
  for (const auto& s : swaths) f.lay(s);
  return f;
}

/// The stream as bytes: headers field by field, then data; what the golden file holds.
std::vector<std::uint8_t> serialise(const std::vector<device::Swath>& swaths) {
  std::vector<std::uint8_t> out;
  auto put = [&](std::int64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  };
  for (const auto& s : swaths) {
    const auto& h = s.header;
    put(h.index, 4); put(h.pass, 2); put(static_cast<int>(h.direction), 1); put(h.first_row, 8);
    put(h.row_step, 2); put(h.rows, 4); put(h.x_start_px, 4); put(h.width_px, 4); put(h.channels, 1);
    put(h.bits_per_pixel, 1); put(h.feed_before_um, 4); put(static_cast<int>(h.compression), 1);
    put(h.raw_bytes, 4); put(static_cast<std::int64_t>(s.data.size()), 4);
    out.insert(out.end(), s.data.begin(), s.data.end());
  }
  return out;
}

TEST(RipJob, SmallJobMatchesGoldenSwathsByteForByte) {
  SmallJob job;
  job.printer.dpi_x = job.printer.dpi_y = 300;  // keeps the golden file small
  RipSettings s;
  s.passes = 2;
  s.bidirectional = true;
  s.threads = 2;
  Collected out;
  auto st = run(job, s, out);
  ASSERT_TRUE(st) << st.error().what();
  const auto bytes = serialise(out.swaths);
  const auto golden = test::source_dir() / "tests/rip/job/golden/small_job_2pass.swaths";
  if (std::getenv("TP_UPDATE_GOLDEN")) {
    std::ofstream(golden, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                  static_cast<std::streamsize>(bytes.size()));
  }
  std::ifstream f(golden, std::ios::binary);
  ASSERT_TRUE(f) << "missing " << golden << " (run with TP_UPDATE_GOLDEN=1 once)";
  std::vector<std::uint8_t> want((std::istreambuf_iterator<char>(f)), {});
  EXPECT_EQ(bytes.size(), want.size());
  EXPECT_TRUE(bytes == want) << "swath stream differs from " << golden;
}

TEST(RipJob, OutputIsIndependentOfBandHeightAndThreads) {
  SmallJob job;
  for (ScreenKind kind : {ScreenKind::kBlueNoise, ScreenKind::kErrorDiffusion}) {
    RipSettings base;
    base.screen = kind;
    base.passes = 4;
    base.band_rows = 16;
    base.threads = 1;
    Collected ref;
    ASSERT_TRUE(run(job, base, ref));
    ASSERT_GT(ref.swaths.size(), 4u);
    for (auto [band, threads] : {std::pair{128, 2}, std::pair{48, 3}, std::pair{4096, 2}}) {
      RipSettings s = base;
      s.band_rows = band;
      s.threads = threads;
      Collected other;
      ASSERT_TRUE(run(job, s, other));
      expect_same_stream(ref.swaths, other.swaths, kind == ScreenKind::kBlueNoise ? "blue noise" : "diffusion");
    }
  }
}

TEST(RipJob, EveryPassPlanPrintsEachDropExactlyOnce) {
  SmallJob job;
  RipSettings single;
  Collected ref;
  auto st = run(job, single, ref);
  ASSERT_TRUE(st);
  const Fabric want = lay_all(ref.swaths, *st);
  EXPECT_EQ(want.doubled, 0);
  // Rows 0 and H-1 belong to the first and last swaths.
  EXPECT_EQ(ref.swaths.front().header.first_row, 0);
  for (int pitch : {1, 2}) {
    job.printer.nozzle_pitch_rows = pitch;
    for (int passes : {1, 2, 4, 8}) {
      RipSettings s;
      s.passes = passes;
      s.skip_blank_swaths = passes % 2 == 0;
      Collected out;
      auto mst = run(job, s, out);
      ASSERT_TRUE(mst) << mst.error().what();
      const Fabric got = lay_all(out.swaths, *mst);
      EXPECT_EQ(got.doubled, 0) << passes << " passes, pitch " << pitch;
      EXPECT_TRUE(got.codes == want.codes) << passes << " passes, pitch " << pitch;
      // With every pass sent, the feeds add up to the travel from the first pass to the last,
      // rounded once (no drift).
      if (!s.skip_blank_swaths) {
        std::uint64_t feed = 0;
        for (const auto& sw : out.swaths) feed += sw.header.feed_before_um;
        const std::int64_t rows = (last_pass(mst->plan, mst->height_px) - first_pass(mst->plan)) * mst->plan.feed_rows;
        EXPECT_EQ(feed, static_cast<std::uint64_t>((rows * 25400 + 300) / 600)) << passes << " passes";
      }
    }
  }
}

TEST(RipJob, DropCountsMatchTheSwaths) {
  SmallJob job;
  Collected out;
  auto st = run(job, RipSettings{}, out);
  ASSERT_TRUE(st);
  const Fabric f = lay_all(out.swaths, *st);
  for (int c = 0; c < 4; ++c) {
    std::array<std::uint64_t, 4> n{};
    for (size_t i = 0; i < static_cast<size_t>(f.width) * f.height; ++i)
      ++n[f.codes[static_cast<size_t>(c) * f.width * f.height + i]];
    for (int k = 1; k < 4; ++k) EXPECT_EQ(st->drops[static_cast<size_t>(c)][static_cast<size_t>(k)], n[static_cast<size_t>(k)]) << c << " " << k;
  }
  EXPECT_GT(st->compression_ratio, 1.0);
  EXPECT_EQ(st->swaths_sent, out.swaths.size());
}

TEST(RipJob, ResumeFromSwathKSendsTheSameSwaths) {
  SmallJob job;
  RipSettings s;
  s.passes = 4;
  Collected all;
  ASSERT_TRUE(run(job, s, all));
  ASSERT_GT(all.swaths.size(), 6u);
  s.first_swath_index = 5;
  Collected rest;
  auto st = run(job, s, rest);
  ASSERT_TRUE(st);
  EXPECT_EQ(st->swaths, all.swaths.size());
  std::vector<device::Swath> tail(all.swaths.begin() + 5, all.swaths.end());
  expect_same_stream(tail, rest.swaths, "resume");
}

TEST(RipJob, BidirectionalAlternatesAndBlankPassesAreSkipped) {
  SmallJob job;
  job.marker.placements.resize(1);  // one piece near the start: the rest of the roll is blank
  RipSettings s;
  s.passes = 2;
  s.bidirectional = true;
  Collected sparse, full;
  auto st = run(job, s, sparse);
  ASSERT_TRUE(st);
  for (size_t i = 0; i < sparse.swaths.size(); ++i)
    EXPECT_EQ(sparse.swaths[i].header.direction,
              i % 2 ? device::CarriageDirection::kRightToLeft : device::CarriageDirection::kLeftToRight);
  s.skip_blank_swaths = false;
  ASSERT_TRUE(run(job, s, full));
  EXPECT_LT(sparse.swaths.size(), full.swaths.size());
  // Trimmed to the inked columns: the piece spans about 14 mm of the 40 mm roll.
  EXPECT_LT(sparse.swaths.front().header.width_px, static_cast<std::uint32_t>(st->width_px / 2));
}

TEST(RipJob, CancelStopsBetweenBandsAndSinkErrorsStopTheJob) {
  SmallJob job;
  geometry::CancelToken cancel;
  Collected out;
  RipSettings s;
  s.band_rows = 64;
  auto st = run(job, s, out, [&](const RipProgress& p) { if (p.band == 2) cancel.cancel(); }, cancel);
  ASSERT_FALSE(st);
  EXPECT_EQ(st.error().code, ErrorCode::kCancelled);

  auto failing = [](device::Swath&&) -> Status { return fail(ErrorCode::kIo, "printer went away"); };
  auto e = rip_marker(job.marker, job.renderer, job.printer, RipSettings{}, failing);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("swath 0: printer went away"), std::string::npos) << e.error().message;
}

TEST(RipJob, ProgressReachesTheEndOfTheRoll) {
  SmallJob job;
  Collected out;
  RipProgress last;
  int calls = 0;
  auto st = run(job, RipSettings{}, out, [&](const RipProgress& p) { last = p, ++calls; });
  ASSERT_TRUE(st);
  EXPECT_EQ(last.rows_done, st->height_px);
  EXPECT_NEAR(last.fabric_y_mm, 30.0, 0.05);
  EXPECT_EQ(calls, static_cast<int>((st->height_px + 127) / 128));
}

TEST(RipJob, SeparationsMatchTheSwaths) {
  SmallJob job;
  auto dir = test::scratch_dir("rip_job_separations");
  RipSettings s;
  s.separations.contone_tiff = dir / "contone.tif";
  s.separations.screened_tiff = dir / "screened.tif";
  Collected out;
  auto st = run(job, s, out);
  ASSERT_TRUE(st) << st.error().what();
  const Fabric f = lay_all(out.swaths, *st);
  auto screened = read_channels8(dir / "screened.tif");
  ASSERT_TRUE(screened) << screened.error().what();
  ASSERT_EQ(screened->channel_names, (std::vector<std::string>{"cyan", "magenta", "yellow", "black"}));
  ASSERT_EQ(screened->width_px, st->width_px);
  size_t mismatches = 0;
  for (int c = 0; c < 4; ++c)
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x)
        mismatches += screened->samples[(static_cast<size_t>(y) * f.width + x) * 4 + c] !=
                      f.codes[(static_cast<size_t>(c) * f.height + y) * f.width + x];
  EXPECT_EQ(mismatches, 0u);
  auto contone = read_channels8(dir / "contone.tif");
  ASSERT_TRUE(contone);
  std::uint64_t ink = 0;
  for (auto v : contone->samples) ink += v;
  EXPECT_GT(ink, 0u);

  s.separations.one_file_per_ink = true;
  s.separations.contone_tiff.clear();
  Collected again;
  ASSERT_TRUE(run(job, s, again));
  auto black = read_channels8(dir / "screened-black.tif");
  ASSERT_TRUE(black) << black.error().what();
  EXPECT_EQ(black->channel_names, std::vector<std::string>{"black"});
  for (int y = 0; y < f.height; y += 7)
    for (int x = 0; x < f.width; x += 3)
      ASSERT_EQ(black->samples[static_cast<size_t>(y) * f.width + x], f.codes[(3 * static_cast<size_t>(f.height) + y) * f.width + x]);
}

TEST(RipJob, BadSettingsAreRefusedWithTheField) {
  SmallJob job;
  Collected out;
  RipSettings s;
  s.band_rows = 100;
  auto a = run(job, s, out);
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("band_rows"), std::string::npos);
  job.marker.width_mm = 2000;  // wider than the printer
  auto b = run(job, RipSettings{}, out);
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("prints at most"), std::string::npos) << b.error().message;
  job.marker.width_mm = 40;
  job.marker.placements.push_back(PiecePlacement{7, 0, false, {}});
  auto c = run(job, RipSettings{}, out);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("placement 3"), std::string::npos) << c.error().message;
}

}  // namespace
}  // namespace tp::rip
