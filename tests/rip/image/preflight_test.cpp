// tests/rip/image/preflight_test.cpp: embedded ICC profiles are validated before OpenImageIO parses
// them (PNG iCCP, JPEG APP2 segments, TIFF tag), and formats are chosen by content.
#include "rip/image/internal/preflight.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <fstream>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <lcms2.h>
#include <zlib.h>

#include "rip/image/image_io.h"
#include "tests/support/image_files.h"
#include "tests/support/paths.h"

namespace tp::rip {
namespace {

namespace OIIO = OIIO_NAMESPACE;
using Bytes = std::vector<std::uint8_t>;

Bytes save_profile(cmsHPROFILE p) {
  cmsUInt32Number n = 0;
  cmsSaveProfileToMem(p, nullptr, &n);
  Bytes bytes(n);
  cmsSaveProfileToMem(p, bytes.data(), &n);
  cmsCloseProfile(p);
  return bytes;
}

/// A wide-gamut RGB profile made by lcms2 (v4: its description is an 'mluc' tag).
Bytes wide_gamut_profile() {
  cmsCIExyY d65{0.3127, 0.3290, 1.0};
  cmsCIExyYTRIPLE primaries{{0.64, 0.33, 1.0}, {0.21, 0.71, 1.0}, {0.15, 0.06, 1.0}};
  cmsToneCurve* gamma = cmsBuildGamma(nullptr, 2.2);
  cmsToneCurve* curves[3] = {gamma, gamma, gamma};
  Bytes b = save_profile(cmsCreateRGBProfile(&d65, &primaries, curves));
  cmsFreeToneCurve(gamma);
  return b;
}

std::uint32_t be32(const std::uint8_t* p) { return std::uint32_t{p[0]} << 24 | p[1] << 16 | p[2] << 8 | p[3]; }
void put_be32(std::uint8_t* p, std::uint32_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 24);
  p[1] = static_cast<std::uint8_t>(v >> 16);
  p[2] = static_cast<std::uint8_t>(v >> 8);
  p[3] = static_cast<std::uint8_t>(v);
}

/// Index of the tag-table entry whose tag data has type `type`, or -1.
int tag_of_type(const Bytes& icc, const char* type) {
  for (std::uint32_t i = 0; i < be32(icc.data() + 128); ++i)
    if (!std::memcmp(icc.data() + be32(icc.data() + 132 + 12 * i + 4), type, 4)) return static_cast<int>(i);
  return -1;
}

/// The shape that crashed OpenImageIO 2.4: a 'text' tag whose size is smaller than its header, so
/// the reader's "size - 8" wraps around.
Bytes truncated_text_tag_profile() {
  Bytes icc = wide_gamut_profile();
  std::uint8_t* entry = icc.data() + 132;
  std::memcpy(icc.data() + be32(entry + 4), "text", 4);
  put_be32(entry + 8, 4);
  return icc;
}

Bytes read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(f)), {});
}

/// A 4x2 RGB8 file in the format of `name`'s extension, optionally with an embedded profile.
Bytes small_image(const std::string& name, const Bytes& icc = {}) {
  auto dir = test::scratch_dir("preflight_src");
  std::uint8_t px[4 * 2 * 3];
  for (int i = 0; i < 24; ++i) px[i] = static_cast<std::uint8_t>(i * 10);
  OIIO::ImageSpec spec(4, 2, 3, OIIO::TypeDesc::UINT8);
  if (!icc.empty()) spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, icc.size()), icc.data());
  test::write_raw_image(dir / name, spec, px);
  return read_file(dir / name);
}

Bytes png_chunk(const char* type, const Bytes& data) {
  Bytes c(8);
  put_be32(c.data(), static_cast<std::uint32_t>(data.size()));
  std::memcpy(c.data() + 4, type, 4);
  c.insert(c.end(), data.begin(), data.end());
  uLong crc = crc32(0, c.data() + 4, static_cast<uInt>(4 + data.size()));
  c.resize(c.size() + 4);
  put_be32(c.data() + c.size() - 4, static_cast<std::uint32_t>(crc));
  return c;
}

/// A PNG with an iCCP chunk (profile name, method 0, `zdata`) inserted after IHDR.
Bytes png_with_iccp(const Bytes& zdata) {
  Bytes png = small_image("plain.png");
  Bytes body = {'w', 'i', 'd', 'e', 0, 0};
  body.insert(body.end(), zdata.begin(), zdata.end());
  Bytes chunk = png_chunk("iCCP", body);
  png.insert(png.begin() + 33, chunk.begin(), chunk.end());  // signature 8 + IHDR 25
  return png;
}

Bytes deflate(const Bytes& raw) {
  uLongf n = compressBound(static_cast<uLong>(raw.size()));
  Bytes z(n);
  EXPECT_EQ(compress(z.data(), &n, raw.data(), static_cast<uLong>(raw.size())), Z_OK);
  z.resize(n);
  return z;
}

/// A JPEG with APP2 ICC_PROFILE segments (sequence number, count, payload) inserted after SOI.
Bytes jpeg_with_segments(const std::vector<std::tuple<int, int, Bytes>>& segments) {
  Bytes jpg = small_image("plain.jpg");
  Bytes app;
  for (const auto& [seq, count, payload] : segments) {
    Bytes data = {'I', 'C', 'C', '_', 'P', 'R', 'O', 'F', 'I', 'L', 'E', 0};
    if (seq >= 0) data.push_back(static_cast<std::uint8_t>(seq));
    if (count >= 0) data.push_back(static_cast<std::uint8_t>(count));
    data.insert(data.end(), payload.begin(), payload.end());
    const std::size_t len = data.size() + 2;
    Bytes seg = {0xff, 0xe2, static_cast<std::uint8_t>(len >> 8), static_cast<std::uint8_t>(len & 0xff)};
    seg.insert(seg.end(), data.begin(), data.end());
    app.insert(app.end(), seg.begin(), seg.end());
  }
  jpg.insert(jpg.begin() + 2, app.begin(), app.end());
  return jpg;
}

std::string refusal(const Bytes& file, const std::string& name) {
  auto r = read_image_from_memory(file, name);
  if (r) return "";
  EXPECT_EQ(r.error().code, ErrorCode::kImage);
  EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
  return r.error().message;
}

TEST(IccCheck, AcceptsProfilesLcmsWrites) {
  EXPECT_TRUE(check_icc_profile(wide_gamut_profile()));
  EXPECT_TRUE(check_icc_profile(save_profile(cmsCreate_sRGBProfile())));
  EXPECT_TRUE(check_icc_profile(save_profile(cmsCreateLab4Profile(nullptr))));
}

TEST(IccCheck, RefusesEachStructuralFault) {
  const Bytes good = wide_gamut_profile();
  struct Case {
    const char* what;
    std::function<void(Bytes&)> spoil;
    const char* expect;
  };
  const int mluc = tag_of_type(good, "mluc");
  ASSERT_GE(mluc, 0);
  const std::vector<Case> cases = {
      {"cut short", [](Bytes& b) { b.resize(b.size() - 10); }, "declares"},
      {"tiny", [](Bytes& b) { b.resize(100); }, "shorter than a header"},
      {"no signature", [](Bytes& b) { std::memcpy(b.data() + 36, "xxxx", 4); }, "'acsp'"},
      {"tag count", [](Bytes& b) { put_be32(b.data() + 128, 100000); }, "tags, more than"},
      {"tag past end", [](Bytes& b) { put_be32(b.data() + 132 + 4, static_cast<std::uint32_t>(b.size() - 4)); },
       "lies outside"},
      {"offset wraps", [](Bytes& b) { put_be32(b.data() + 132 + 4, 0xfffffff0u); }, "lies outside"},
      {"text too short", [](Bytes& b) { b = truncated_text_tag_profile(); }, "too short for any tag type"},
      {"desc too short",
       [](Bytes& b) {
         std::memcpy(b.data() + be32(b.data() + 132 + 4), "desc", 4);
         put_be32(b.data() + 132 + 8, 10);
       },
       "too short for type 'desc'"},
      {"mluc records",
       [&](Bytes& b) {
         std::uint8_t* d = b.data() + be32(b.data() + 132 + 12 * mluc + 4);
         put_be32(d + 8, 1000);
       },
       "record table"},
      {"mluc string",
       [&](Bytes& b) {
         std::uint8_t* d = b.data() + be32(b.data() + 132 + 12 * mluc + 4);
         put_be32(d + 16 + 8, 0x7fffffff);
       },
       "string outside"},
  };
  for (const auto& c : cases) {
    Bytes b = good;
    c.spoil(b);
    auto r = check_icc_profile(b);
    ASSERT_FALSE(r) << c.what;
    EXPECT_NE(r.error().message.find(c.expect), std::string::npos) << c.what << ": " << r.error().message;
    EXPECT_EQ(r.error().message.rfind("embedded ICC profile", 0), 0u) << r.error().message;
  }
}

TEST(Preflight, PngProfileWithTruncatedTextTagIsRefusedBeforeDecoding) {
  const std::string msg = refusal(png_with_iccp(deflate(truncated_text_tag_profile())), "crash.png");
  EXPECT_NE(msg.find("embedded ICC profile tag"), std::string::npos) << msg;
}

TEST(Preflight, PngWithSoundProfileIsReadAndConverted) {
  Bytes plain = small_image("plain.png");
  auto raw = read_image_from_memory(plain, "plain.png");
  auto wide = read_image_from_memory(png_with_iccp(deflate(wide_gamut_profile())), "wide.png");
  ASSERT_TRUE(raw && wide) << (wide ? raw.error().what() : wide.error().what());
  // Same samples, but read through the wide-gamut profile: colours must move.
  int moved = 0;
  for (std::size_t i = 0; i < raw->pixels.size(); ++i) moved += raw->pixels[i] != wide->pixels[i];
  EXPECT_GT(moved, 4);
}

TEST(Preflight, PngProfileStreamThatDoesNotInflateIsRefused) {
  Bytes z = deflate(wide_gamut_profile());
  for (std::size_t i = 10; i < z.size(); i += 7) z[i] ^= 0x5a;
  EXPECT_NE(refusal(png_with_iccp(z), "z.png").find("does not inflate"), std::string::npos);
}

TEST(Preflight, JpegProfileSegmentsAreAssembledAndChecked) {
  const Bytes icc = wide_gamut_profile();
  const Bytes first(icc.begin(), icc.begin() + 200), rest(icc.begin() + 200, icc.end());
  // Segments out of order are fine: they are put together by sequence number.
  auto split = read_image_from_memory(jpeg_with_segments({{2, 2, rest}, {1, 2, first}}), "split.jpg");
  ASSERT_TRUE(split) << split.error().what();

  EXPECT_NE(refusal(jpeg_with_segments({{1, 2, first}}), "missing.jpg").find("segment 2 of 2 is missing"),
            std::string::npos);
  EXPECT_NE(refusal(jpeg_with_segments({{1, 1, first}, {1, 1, rest}}), "twice.jpg").find("appears twice"),
            std::string::npos);
  EXPECT_NE(refusal(jpeg_with_segments({{0, 1, icc}}), "zero.jpg").find("out of range"), std::string::npos);
  EXPECT_NE(refusal(jpeg_with_segments({{-1, -1, {}}}), "short.jpg").find("14-byte header"), std::string::npos);
  EXPECT_NE(refusal(jpeg_with_segments({{1, 1, truncated_text_tag_profile()}}), "text.jpg").find("too short"),
            std::string::npos);
}

/// A JPEG with an APP13 Photoshop IPTC resource whose IIM block is `iim`, declared `declared` long.
Bytes jpeg_with_iptc(const Bytes& iim, std::size_t declared) {
  Bytes jpg = small_image("plain.jpg");
  Bytes data = {'P', 'h', 'o', 't', 'o', 's', 'h', 'o', 'p', ' ', '3', '.', '0', 0, '8', 'B', 'I', 'M', 0x04, 0x04,
                0, 0, 0, 0, static_cast<std::uint8_t>(declared >> 8), static_cast<std::uint8_t>(declared & 0xff)};
  data.insert(data.end(), iim.begin(), iim.end());
  const std::size_t len = data.size() + 2;
  Bytes seg = {0xff, 0xed, static_cast<std::uint8_t>(len >> 8), static_cast<std::uint8_t>(len & 0xff)};
  seg.insert(seg.end(), data.begin(), data.end());
  jpg.insert(jpg.begin() + 2, seg.begin(), seg.end());
  return jpg;
}

TEST(Preflight, JpegIptcRecordsMustLieInsideTheirBlock) {
  const Bytes caption = {0x1c, 0x02, 0x78, 0x00, 0x05, 'h', 'e', 'l', 'l', 'o'};
  auto good = read_image_from_memory(jpeg_with_iptc(caption, caption.size()), "iptc.jpg");
  EXPECT_TRUE(good) << good.error().what();
  Bytes long_record = caption;
  long_record[4] = 0x40;  // claims 64 bytes, holds 5
  EXPECT_NE(refusal(jpeg_with_iptc(long_record, long_record.size()), "rec.jpg").find("past the block's end"),
            std::string::npos);
  EXPECT_NE(refusal(jpeg_with_iptc(caption, 4000), "block.jpg").find("runs past its segment"), std::string::npos);
  Bytes cut_header = {0x1c, 0x02};
  EXPECT_NE(refusal(jpeg_with_iptc(cut_header, 2), "head.jpg").find("record header"), std::string::npos);
}

TEST(Preflight, JpegCutShortIsRefusedAndProgressiveJpegIsRead) {
  // libjpeg decodes a truncated file as grey rows with a warning; it must not reach the RIP.
  Bytes jpg = small_image("whole.jpg");
  for (std::size_t keep : {jpg.size() - 2, jpg.size() / 2, std::size_t{200}}) {
    Bytes cut(jpg.begin(), jpg.begin() + static_cast<std::ptrdiff_t>(keep));
    EXPECT_NE(refusal(cut, "cut.jpg").find("ends before its end-of-image marker"), std::string::npos) << keep;
  }
  auto dir = test::scratch_dir("preflight_progressive");
  std::uint8_t px[64 * 64 * 3];
  for (int i = 0; i < 64 * 64 * 3; ++i) px[i] = static_cast<std::uint8_t>(i * 7);
  OIIO::ImageSpec spec(64, 64, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("jpeg:progressive", 1);
  test::write_raw_image(dir / "p.jpg", spec, px);
  Bytes prog = read_file(dir / "p.jpg");
  int scans = 0;
  for (std::size_t i = 0; i + 1 < prog.size(); ++i) scans += prog[i] == 0xff && prog[i + 1] == 0xda;
  ASSERT_GT(scans, 1) << "not a progressive file";
  auto r = read_image_from_memory(prog, "p.jpg");
  EXPECT_TRUE(r) << r.error().what();
}

TEST(Preflight, TiffProfileIsChecked) {
  Bytes bad = wide_gamut_profile();
  put_be32(bad.data() + 132 + 8, static_cast<std::uint32_t>(bad.size()));  // first tag runs past the end
  EXPECT_NE(refusal(small_image("bad.tif", bad), "bad.tif").find("lies outside"), std::string::npos);
  auto good = read_image_from_memory(small_image("good.tif", wide_gamut_profile()), "good.tif");
  EXPECT_TRUE(good) << good.error().what();
}

/// A 1x1 RGB8 little-endian uncompressed TIFF carrying `extra` as tag `tag` of type UNDEFINED.
Bytes tiff_with_tag(std::uint16_t tag, const Bytes& extra) {
  auto le16 = [](Bytes& b, unsigned v) { b.push_back(v & 0xff), b.push_back((v >> 8) & 0xff); };
  auto le32 = [&](Bytes& b, std::uint32_t v) { le16(b, v & 0xffff), le16(b, v >> 16); };
  const std::uint32_t pixels_at = 8, bps_at = 11, extra_at = 18;
  const std::uint32_t ifd_at = extra_at + static_cast<std::uint32_t>(extra.size() + (extra.size() & 1));
  Bytes t = {'I', 'I', 42, 0};
  le32(t, ifd_at);
  t.insert(t.end(), {200, 100, 50});  // the pixel
  for (int i = 0; i < 3; ++i) le16(t, 8);
  t.push_back(0);  // pad to extra_at
  t.insert(t.end(), extra.begin(), extra.end());
  if (extra.size() & 1) t.push_back(0);
  struct Entry { std::uint16_t tag, type; std::uint32_t count, value; };
  const std::vector<Entry> entries = {{256, 3, 1, 1},       {257, 3, 1, 1}, {258, 3, 3, bps_at}, {259, 3, 1, 1},
                                      {262, 3, 1, 2},       {273, 4, 1, pixels_at}, {277, 3, 1, 3}, {278, 3, 1, 1},
                                      {279, 4, 1, 3},       {tag, 7, static_cast<std::uint32_t>(extra.size()), extra_at}};
  le16(t, static_cast<unsigned>(entries.size()));
  for (const Entry& e : entries) {
    le16(t, e.tag), le16(t, e.type), le32(t, e.count), le32(t, e.value);
  }
  le32(t, 0);
  return t;
}

TEST(Preflight, TiffIptcRecordsAreChecked) {
  const Bytes caption = {0x1c, 0x02, 0x78, 0x00, 0x05, 'h', 'e', 'l', 'l', 'o'};
  auto good = read_image_from_memory(tiff_with_tag(33723, caption), "iptc.tif");
  ASSERT_TRUE(good) << good.error().what();
  EXPECT_EQ(good->at(0, 0), (geometry::Rgba8{200, 100, 50, 255}));
  Bytes long_record = caption;
  long_record[3] = 0x7f;  // claims 32 KB, holds 5 bytes
  EXPECT_NE(refusal(tiff_with_tag(33723, long_record), "rec.tif").find("IPTC record at byte 0"), std::string::npos);
  Bytes bad_icc = wide_gamut_profile();
  bad_icc.resize(bad_icc.size() - 1);
  EXPECT_NE(refusal(tiff_with_tag(34675, bad_icc), "icc.tif").find("declares"), std::string::npos);
}

TEST(Preflight, FormatIsTakenFromContentNotName) {
  auto png_named_jpg = read_image_from_memory(small_image("p.png"), "design.jpg");
  EXPECT_TRUE(png_named_jpg) << png_named_jpg.error().what();
  const std::string bmp = refusal(small_image("b.bmp"), "design.png");
  EXPECT_NE(bmp.find("not a PNG, JPEG, TIFF or OpenEXR image"), std::string::npos) << bmp;
  EXPECT_NE(refusal({}, "empty.png").find("empty"), std::string::npos);
}

}  // namespace
}  // namespace tp::rip
