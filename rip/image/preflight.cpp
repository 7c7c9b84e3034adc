// rip/image/preflight.cpp: container sniffing and embedded ICC profile validation (PNG iCCP chunk,
// JPEG APP2 ICC_PROFILE segments, TIFF tag 34675), before OpenImageIO decodes anything.
#include "rip/image/internal/preflight.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <zlib.h>

namespace tp::rip {

namespace {

namespace OIIO = OIIO_NAMESPACE;

/// Largest embedded profile accepted (device-link and multi-ink printer profiles reach a few MB).
constexpr std::size_t kMaxIccBytes = std::size_t{64} << 20;
/// Tags in a profile: real ones have a few dozen.
constexpr std::uint32_t kMaxIccTags = 4096;

std::uint32_t be32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

std::unexpected<Error> icc_error(std::string what) { return fail(ErrorCode::kImage, "embedded ICC profile " + what); }

std::string printable(const std::uint8_t* sig) {
  std::string s;
  for (int i = 0; i < 4; ++i) s += sig[i] >= 0x20 && sig[i] < 0x7f ? static_cast<char>(sig[i]) : '?';
  return s;
}

/// IPTC-IIM records (0x1C, record, dataset, 2-byte size, data) must each lie inside the block:
/// OpenImageIO 2.4 walks them trusting every size field.
Status check_iptc_records(std::span<const std::uint8_t> iim) {
  std::size_t pos = 0;
  while (pos < iim.size() && iim[pos] == 0x1c) {
    if (iim.size() - pos < 5) return fail(ErrorCode::kImage, "IPTC block ends inside a record header");
    const std::size_t n = std::size_t{iim[pos + 3]} << 8 | iim[pos + 4];
    if (n > iim.size() - pos - 5)
      return fail(ErrorCode::kImage, fmt::format("IPTC record at byte {} claims {} bytes past the block's end", pos, n));
    pos += 5 + n;
  }
  return {};
}

/// Reads exactly `n` bytes at `offset`; false when the file is shorter.
bool read_at(OIIO::Filesystem::IOProxy& io, std::uint64_t offset, void* buf, std::size_t n) {
  if (n == 0) return true;
  if (offset > static_cast<std::uint64_t>(INT64_MAX)) return false;
  return io.pread(buf, n, static_cast<std::int64_t>(offset)) == n;
}

// ---- PNG --------------------------------------------------------------------------------------

/// Inflates an iCCP chunk's zlib stream, refusing output above kMaxIccBytes.
Result<std::vector<std::uint8_t>> inflate_profile(std::span<const std::uint8_t> z) {
  z_stream s{};
  if (inflateInit(&s) != Z_OK) return icc_error("cannot be decompressed (zlib initialisation failed)");
  std::vector<std::uint8_t> out(std::min<std::size_t>(std::max<std::size_t>(z.size() * 4, 4096), kMaxIccBytes));
  s.next_in = const_cast<Bytef*>(z.data());
  s.avail_in = static_cast<uInt>(z.size());
  int rc = Z_OK;
  while (rc == Z_OK) {
    if (s.total_out == out.size()) {
      if (out.size() >= kMaxIccBytes) {
        inflateEnd(&s);
        return icc_error(fmt::format("is larger than {} MiB", kMaxIccBytes >> 20));
      }
      out.resize(std::min(out.size() * 2, kMaxIccBytes));
    }
    s.next_out = out.data() + s.total_out;
    s.avail_out = static_cast<uInt>(out.size() - s.total_out);
    rc = inflate(&s, Z_NO_FLUSH);
  }
  const std::size_t produced = s.total_out;
  inflateEnd(&s);
  if (rc != Z_STREAM_END) return icc_error("is corrupt: its compressed data does not inflate");
  out.resize(produced);
  return out;
}

Status check_png(OIIO::Filesystem::IOProxy& io) {
  std::uint64_t pos = 8;
  bool seen_profile = false;
  for (;;) {
    std::uint8_t head[8];
    if (!read_at(io, pos, head, 8)) return {};  // truncated: the decoder reports it
    const std::uint32_t len = be32(head);
    const std::uint8_t* type = head + 4;
    if (len > 0x7fffffffu) return {};            // invalid per the PNG spec: libpng refuses it
    if (!std::memcmp(type, "IDAT", 4) || !std::memcmp(type, "IEND", 4)) return {};
    if (!std::memcmp(type, "iCCP", 4)) {
      if (seen_profile) return icc_error("appears twice (two iCCP chunks)");
      seen_profile = true;
      if (len > kMaxIccBytes) return icc_error(fmt::format("chunk is larger than {} MiB", kMaxIccBytes >> 20));
      std::vector<std::uint8_t> data(len);
      if (!read_at(io, pos + 8, data.data(), len)) return icc_error("chunk is truncated");
      // Profile name (1-79 Latin-1 bytes), NUL, compression method 0, zlib stream.
      auto nul = std::find(data.begin(), data.begin() + std::min<std::size_t>(len, 80), std::uint8_t{0});
      if (nul == data.begin() || nul == data.begin() + std::min<std::size_t>(len, 80))
        return icc_error("chunk has no valid profile name");
      const std::size_t at = static_cast<std::size_t>(nul - data.begin()) + 1;
      if (at >= len || data[at] != 0) return icc_error("chunk names an unknown compression method");
      auto icc = inflate_profile(std::span(data).subspan(at + 1));
      if (!icc) return std::unexpected(icc.error());
      if (auto ok = check_icc_profile(*icc); !ok) return ok;
    }
    pos += std::uint64_t{len} + 12;
  }
}

// ---- JPEG -------------------------------------------------------------------------------------

std::unexpected<Error> jpeg_cut_short() {
  return fail(ErrorCode::kImage, "JPEG data ends before its end-of-image marker (file cut short?)");
}

/// Walks from the first scan header to the end-of-image marker: entropy-coded data (stuffed 0xFF00
/// bytes, restart markers) and, in progressive files, further tables and scans. libjpeg takes a
/// file that ends early as a warning and fills the missing rows with grey, and OpenImageIO passes
/// that on as success; a design cut short in transfer must be refused, not printed half grey.
Status check_jpeg_reaches_eoi(OIIO::Filesystem::IOProxy& io, std::uint64_t pos) {
  std::vector<std::uint8_t> buf(std::size_t{1} << 16);
  std::uint64_t buf_at = 0;
  std::size_t buf_len = 0;
  auto byte_at = [&](std::uint64_t p, std::uint8_t& b) {
    if (p < buf_at || p >= buf_at + buf_len) {
      if (p > static_cast<std::uint64_t>(INT64_MAX)) return false;
      buf_at = p;
      buf_len = io.pread(buf.data(), buf.size(), static_cast<std::int64_t>(p));
      if (buf_len == 0) return false;
    }
    b = buf[static_cast<std::size_t>(p - buf_at)];
    return true;
  };
  auto segment_end = [&](std::uint64_t p) -> std::optional<std::uint64_t> {  // p: first length byte
    std::uint8_t hi = 0, lo = 0;
    if (!byte_at(p, hi) || !byte_at(p + 1, lo)) return std::nullopt;
    const std::uint64_t len = std::uint64_t{hi} << 8 | lo;
    if (len < 2) return std::nullopt;
    return p + len;
  };
  auto next = segment_end(pos);  // the scan header
  if (!next) return jpeg_cut_short();
  pos = *next;
  for (std::uint8_t b = 0;;) {
    if (!byte_at(pos, b)) return jpeg_cut_short();
    if (b != 0xff) {  // skip entropy-coded bytes up to the next 0xFF in the buffer
      const std::uint8_t* from = buf.data() + (pos - buf_at);
      const void* ff = std::memchr(from, 0xff, static_cast<std::size_t>(buf.data() + buf_len - from));
      pos = ff ? pos + static_cast<std::uint64_t>(static_cast<const std::uint8_t*>(ff) - from) : buf_at + buf_len;
      continue;
    }
    ++pos;
    std::uint8_t m = 0xff;
    while (m == 0xff) {
      if (!byte_at(pos, m)) return jpeg_cut_short();
      ++pos;
    }
    if (m == 0x00 || (m >= 0xd0 && m <= 0xd7)) continue;  // stuffed byte, restart marker
    if (m == 0xd9) return {};
    next = segment_end(pos);  // tables or another scan (progressive)
    if (!next) return jpeg_cut_short();
    pos = *next;
  }
}

Status check_jpeg(OIIO::Filesystem::IOProxy& io) {
  constexpr char kIccId[] = "ICC_PROFILE";  // 11 characters and a NUL
  constexpr std::size_t kIccHeader = 14;    // id, sequence number, count
  std::array<std::vector<std::uint8_t>, 256> parts;
  std::array<bool, 256> present{};
  int count = 0;
  std::uint64_t pos = 2;
  for (;;) {
    std::uint8_t b = 0;
    if (!read_at(io, pos, &b, 1)) return jpeg_cut_short();
    if (b != 0xff) break;  // not at a marker: the decoder reports the corruption
    std::uint8_t marker = 0xff;
    while (marker == 0xff) {
      if (!read_at(io, ++pos, &marker, 1)) return jpeg_cut_short();
    }
    ++pos;
    if (marker == 0xda) {  // start of scan: the rest of the file must reach the end-of-image marker
      if (auto s = check_jpeg_reaches_eoi(io, pos); !s) return s;
      break;
    }
    if (marker == 0xd9) break;                                        // end of image
    if ((marker >= 0xd0 && marker <= 0xd7) || marker == 0x01) continue;  // no length
    std::uint8_t lb[2];
    if (!read_at(io, pos, lb, 2)) return jpeg_cut_short();
    const std::size_t len = std::size_t{lb[0]} << 8 | lb[1];
    if (len < 2) return {};
    // APP13 (Photoshop resources) and APP2 (ICC profile) are what OpenImageIO parses itself.
    std::vector<std::uint8_t> seg;
    if (marker == 0xed || marker == 0xe2) {
      seg.resize(len - 2);
      if (!read_at(io, pos + 2, seg.data(), seg.size())) return jpeg_cut_short();
    }
    if (marker == 0xed) {
      // "Photoshop 3.0", NUL, "8BIM", type 1028 (IPTC), name, size, IIM data.
      constexpr char kPs[] = "Photoshop 3.0";
      if (seg.size() >= sizeof kPs && !std::memcmp(seg.data(), kPs, sizeof kPs)) {
        if (seg.size() < 26) return fail(ErrorCode::kImage, "APP13 Photoshop segment is too short for a resource");
        if (!std::memcmp(seg.data() + 14, "8BIM", 4) && (seg[18] << 8 | seg[19]) == 1028) {
          const std::size_t n = std::size_t{seg[24]} << 8 | seg[25];
          if (26 + n > seg.size()) return fail(ErrorCode::kImage, "APP13 IPTC resource runs past its segment");
          if (auto s = check_iptc_records(std::span(seg).subspan(26, n)); !s) return s;
        }
      }
    }
    if (marker == 0xe2) {
      // Decoders compare the segment with "ICC_PROFILE" as a C string: it must hold a NUL.
      if (std::find(seg.begin(), seg.end(), std::uint8_t{0}) == seg.end())
        return fail(ErrorCode::kImage, "APP2 segment is not NUL-terminated");
      if (seg.size() >= sizeof kIccId && !std::memcmp(seg.data(), kIccId, sizeof kIccId)) {
        if (seg.size() < kIccHeader) return icc_error("segment is shorter than its 14-byte header");
        const int seq = seg[12], n = seg[13];
        if (count == 0) count = n;
        if (n != count) return icc_error(fmt::format("segments disagree on their count ({} and {})", count, n));
        if (seq == 0 || seq > count) return icc_error(fmt::format("segment number {} of {} is out of range", seq, count));
        if (present[seq]) return icc_error(fmt::format("segment {} of {} appears twice", seq, count));
        present[seq] = true;
        parts[seq].assign(seg.begin() + kIccHeader, seg.end());
      }
    }
    pos += len;
  }
  if (count == 0) return {};
  std::vector<std::uint8_t> icc;
  for (int s = 1; s <= count; ++s) {
    if (!present[s]) return icc_error(fmt::format("segment {} of {} is missing", s, count));
    icc.insert(icc.end(), parts[s].begin(), parts[s].end());
  }
  return check_icc_profile(icc);
}

// ---- TIFF -------------------------------------------------------------------------------------

Status check_tiff(OIIO::Filesystem::IOProxy& io, bool little, bool big) {
  auto u16 = [&](const std::uint8_t* p) { return little ? std::uint16_t(p[0] | p[1] << 8) : std::uint16_t(p[0] << 8 | p[1]); };
  auto u32 = [&](const std::uint8_t* p) {
    return little ? std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24
                  : be32(p);
  };
  auto u64 = [&](const std::uint8_t* p) {
    return little ? std::uint64_t{u32(p)} | std::uint64_t{u32(p + 4)} << 32 : std::uint64_t{u32(p)} << 32 | u32(p + 4);
  };
  std::uint8_t head[16];
  if (!read_at(io, 0, head, big ? 16 : 8)) return {};
  const std::uint64_t ifd = big ? u64(head + 8) : u32(head + 4);
  std::uint8_t cnt[8];
  if (!read_at(io, ifd, cnt, big ? 8 : 2)) return {};  // libtiff reports a bad directory
  const std::uint64_t entries = big ? u64(cnt) : u16(cnt);
  const std::size_t entry_size = big ? 20 : 12;
  if (entries > 65535) return {};
  std::vector<std::uint8_t> table(static_cast<std::size_t>(entries) * entry_size);
  if (!read_at(io, ifd + (big ? 8 : 2), table.data(), table.size())) return {};
  // Bytes of an entry's value, inline or at its offset; nullopt when the file is shorter.
  auto value = [&](const std::uint8_t* e, std::uint64_t n) -> std::optional<std::vector<std::uint8_t>> {
    std::vector<std::uint8_t> v(static_cast<std::size_t>(n));
    if (n <= (big ? 8u : 4u)) std::memcpy(v.data(), e + (big ? 12 : 8), v.size());
    else if (!read_at(io, big ? u64(e + 12) : u32(e + 8), v.data(), v.size())) return std::nullopt;
    return v;
  };
  for (std::uint64_t i = 0; i < entries; ++i) {
    const std::uint8_t* e = table.data() + i * entry_size;
    if (u16(e) == 33723) {  // TIFFTAG_RICHTIFFIPTC: IPTC-IIM records, stored as BYTE, UNDEFINED or LONG
      const std::uint16_t type = u16(e + 2);
      const std::uint64_t unit = type == 4 ? 4 : type == 1 || type == 7 ? 1 : 0;
      const std::uint64_t count = big ? u64(e + 4) : u32(e + 4);
      if (unit == 0 || count > kMaxIccBytes / unit) return fail(ErrorCode::kImage, "IPTC tag has an invalid type or size");
      auto v = value(e, count * unit);
      if (!v) return fail(ErrorCode::kImage, "IPTC tag is truncated");
      if (auto s = check_iptc_records(*v); !s) return s;
      continue;
    }
    if (u16(e) != 34675) continue;  // TIFFTAG_ICCPROFILE
    const std::uint16_t type = u16(e + 2);
    if (type != 7 && type != 1) return icc_error(fmt::format("tag has TIFF type {}, not UNDEFINED", type));
    const std::uint64_t n = big ? u64(e + 4) : u32(e + 4);
    if (n > kMaxIccBytes) return icc_error(fmt::format("is larger than {} MiB", kMaxIccBytes >> 20));
    auto icc = value(e, n);
    if (!icc) return icc_error("is truncated");
    if (auto s = check_icc_profile(*icc); !s) return s;
  }
  return {};
}

}  // namespace

std::string_view oiio_format_name(ImageFormat format) {
  switch (format) {
    case ImageFormat::kPng: return "png";
    case ImageFormat::kJpeg: return "jpeg";
    case ImageFormat::kTiff: return "tiff";
    case ImageFormat::kOpenExr: return "openexr";
  }
  return "png";
}

Status check_icc_profile(std::span<const std::uint8_t> icc) {
  const std::uint64_t size = icc.size();
  if (size < 132) return icc_error(fmt::format("is {} bytes, shorter than a header and tag count", size));
  if (be32(icc.data()) != size)
    return icc_error(fmt::format("declares {} bytes but holds {}", be32(icc.data()), size));
  if (std::memcmp(icc.data() + 36, "acsp", 4)) return icc_error("lacks the 'acsp' signature");
  const std::uint32_t tags = be32(icc.data() + 128);
  if (tags > kMaxIccTags || 132 + std::uint64_t{tags} * 12 > size)
    return icc_error(fmt::format("declares {} tags, more than its {} bytes hold", tags, size));
  for (std::uint32_t i = 0; i < tags; ++i) {
    const std::uint8_t* t = icc.data() + 132 + std::size_t{i} * 12;
    const std::string sig = printable(t);
    const std::uint64_t off = be32(t + 4), len = be32(t + 8);
    if (len < 8) return icc_error(fmt::format("tag '{}' is {} bytes, too short for any tag type", sig, len));
    if (off + len > size)
      return icc_error(fmt::format("tag '{}' ({} bytes at offset {}) lies outside the profile's {} bytes", sig, len,
                                   off, size));
    const std::uint8_t* d = icc.data() + off;
    const std::string type = printable(d);
    if (type == "desc" && len < 12) return icc_error(fmt::format("tag '{}' is too short for type 'desc'", sig));
    if (type == "mluc") {
      if (len < 16) return icc_error(fmt::format("tag '{}' is too short for type 'mluc'", sig));
      const std::uint64_t records = be32(d + 8), record_size = be32(d + 12);
      if (record_size != 12 || 16 + records * 12 > len)
        return icc_error(fmt::format("tag '{}' has a record table that does not fit the tag", sig));
      for (std::uint64_t r = 0; r < records; ++r) {
        const std::uint8_t* rec = d + 16 + r * 12;
        const std::uint64_t str_len = be32(rec + 4), str_off = be32(rec + 8);
        if (str_off + str_len > len)
          return icc_error(fmt::format("tag '{}' has a string outside the tag", sig));
      }
    }
  }
  return {};
}

Result<ImageFormat> preflight_image(const std::string& name, OIIO::Filesystem::IOProxy& io) {
  std::uint8_t magic[8] = {};
  const std::size_t got = io.pread(magic, sizeof magic, 0);
  auto with_name = [&](Status s) -> Status {
    if (!s) return fail(s.error().with_context(name));
    return s;
  };
  static constexpr std::uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got == 8 && !std::memcmp(magic, kPng, 8)) {
    if (auto s = with_name(check_png(io)); !s) return std::unexpected(s.error());
    return ImageFormat::kPng;
  }
  if (got >= 3 && magic[0] == 0xff && magic[1] == 0xd8 && magic[2] == 0xff) {
    if (auto s = with_name(check_jpeg(io)); !s) return std::unexpected(s.error());
    return ImageFormat::kJpeg;
  }
  const bool ii = got >= 4 && magic[0] == 'I' && magic[1] == 'I', mm = got >= 4 && magic[0] == 'M' && magic[1] == 'M';
  if (ii || mm) {
    const int version = ii ? magic[2] | magic[3] << 8 : magic[2] << 8 | magic[3];
    if (version == 42 || version == 43) {
      if (auto s = with_name(check_tiff(io, ii, version == 43)); !s) return std::unexpected(s.error());
      return ImageFormat::kTiff;
    }
  }
  if (got >= 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01)
    return ImageFormat::kOpenExr;
  if (got == 0) return fail(ErrorCode::kImage, name + ": empty or unreadable image file");
  return fail(ErrorCode::kImage, name + ": not a PNG, JPEG, TIFF or OpenEXR image (by its content)");
}

}  // namespace tp::rip
