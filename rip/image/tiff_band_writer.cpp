// rip/image/tiff_band_writer.cpp: a streaming baseline TIFF / BigTIFF writer for separations: strips
// go to disk as rows arrive (PackBits, Deflate or raw), the directory is written last.
//
// Written here rather than through OpenImageIO because separations arrive already packed at 1 or
// 2 bits: OIIO would unpack them to bytes and re-pack them per sample, which cost more than
// screening them.
#include "rip/image/tiff_band_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <spdlog/fmt/fmt.h>
#include <zlib.h>

#include "rip/image/internal/tiff_channels.h"
#include "rip/swath/packbits.h"

namespace tp::rip {

namespace {

constexpr std::size_t kTargetStripBytes = 256 * 1024;  ///< strips of about this much raw data
constexpr int kMaxRowsPerStrip = 256;
constexpr double kBigTiffThresholdBytes = 3.5e9;       ///< past this a classic TIFF's offsets may overflow

enum TiffType : std::uint16_t { kShort = 3, kLong = 4, kRational = 5, kAscii = 2, kLong8 = 16 };

/// One directory entry before layout: its values as raw little-endian bytes.
struct Entry {
  std::uint16_t tag;
  std::uint16_t type;
  std::uint64_t count;
  std::vector<std::uint8_t> bytes;
};

void put_le(std::vector<std::uint8_t>& out, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

Entry shorts(std::uint16_t tag, const std::vector<std::uint16_t>& v) {
  Entry e{tag, kShort, v.size(), {}};
  for (auto x : v) put_le(e.bytes, x, 2);
  return e;
}
Entry longs(std::uint16_t tag, const std::vector<std::uint32_t>& v) {
  Entry e{tag, kLong, v.size(), {}};
  for (auto x : v) put_le(e.bytes, x, 4);
  return e;
}
Entry offsets(std::uint16_t tag, const std::vector<std::uint64_t>& v, bool big) {
  Entry e{tag, static_cast<std::uint16_t>(big ? kLong8 : kLong), v.size(), {}};
  for (auto x : v) put_le(e.bytes, x, big ? 8 : 4);
  return e;
}
Entry ascii(std::uint16_t tag, const std::string& s) {
  Entry e{tag, kAscii, s.size() + 1, {}};
  e.bytes.assign(s.begin(), s.end());
  e.bytes.push_back(0);
  return e;
}
Entry rational(std::uint16_t tag, std::uint32_t num, std::uint32_t den) {
  Entry e{tag, kRational, 1, {}};
  put_le(e.bytes, num, 4);
  put_le(e.bytes, den, 4);
  return e;
}

}  // namespace

struct TiffBandWriter::Impl {
  std::string name;
  std::FILE* file = nullptr;
  int width = 0, channels = 0, bits = 8;
  std::int64_t height = 0, next_row = 0;
  TiffCompression compression = TiffCompression::kPackBits;
  bool big = false;
  std::string description;
  double dpi_x = 0, dpi_y = 0;
  int rows_per_strip = 1;
  std::size_t row_bytes = 0;               ///< packed bytes of one row (all samples)
  std::vector<std::uint8_t> strip;         ///< packed rows of the strip being filled
  int strip_rows = 0;
  std::vector<std::uint8_t> encoded;
  std::vector<std::uint64_t> strip_offsets, strip_sizes;
  std::uint64_t file_pos = 0;
  bool closed = false;

  Status write_bytes(const void* data, std::size_t n) {
    if (n && std::fwrite(data, 1, n, file) != n)
      return fail(ErrorCode::kIo, fmt::format("{}: write failed at byte {}", name, file_pos));
    file_pos += n;
    return {};
  }

  /// Compresses and writes the filled strip.
  Status flush_strip() {
    if (strip_rows == 0) return {};
    const std::size_t raw = static_cast<std::size_t>(strip_rows) * row_bytes;
    const std::uint8_t* data = strip.data();
    std::size_t size = raw;
    if (compression == TiffCompression::kPackBits) {
      // TIFF PackBits restarts at every row.
      encoded.resize(static_cast<std::size_t>(strip_rows) * packbits_max_size(row_bytes));
      size = 0;
      for (int r = 0; r < strip_rows; ++r)
        size += packbits_encode({strip.data() + static_cast<std::size_t>(r) * row_bytes, row_bytes}, encoded.data() + size);
      data = encoded.data();
    } else if (compression == TiffCompression::kDeflate) {
      uLongf n = compressBound(static_cast<uLong>(raw));
      encoded.resize(n);
      if (compress2(encoded.data(), &n, strip.data(), static_cast<uLong>(raw), Z_BEST_SPEED) != Z_OK)
        return fail(ErrorCode::kIo, fmt::format("{}: deflate failed", name));
      size = n;
      data = encoded.data();
    }
    strip_offsets.push_back(file_pos);
    strip_sizes.push_back(size);
    strip_rows = 0;
    return write_bytes(data, size);
  }

  /// Writes the directory at the end of the file and points the header at it.
  Status write_directory() {
    std::vector<Entry> entries;
    entries.push_back(longs(256, {static_cast<std::uint32_t>(width)}));
    entries.push_back(longs(257, {static_cast<std::uint32_t>(height)}));
    entries.push_back(shorts(258, std::vector<std::uint16_t>(static_cast<std::size_t>(channels), static_cast<std::uint16_t>(bits))));
    const std::uint16_t comp = compression == TiffCompression::kPackBits ? 32773
                               : compression == TiffCompression::kDeflate ? 8
                                                                          : 1;
    entries.push_back(shorts(259, {comp}));
    entries.push_back(shorts(262, {1}));  // min-is-black: a sample is the ink amount
    entries.push_back(ascii(270, description));
    entries.push_back(offsets(273, strip_offsets, big));
    entries.push_back(shorts(277, {static_cast<std::uint16_t>(channels)}));
    entries.push_back(longs(278, {static_cast<std::uint32_t>(rows_per_strip)}));
    entries.push_back(offsets(279, strip_sizes, big));
    if (dpi_x > 0 && dpi_y > 0) {
      // Hundredths of a dot per inch keep fractional resolutions.
      entries.push_back(rational(282, static_cast<std::uint32_t>(std::lround(dpi_x * 100)), 100));
      entries.push_back(rational(283, static_cast<std::uint32_t>(std::lround(dpi_y * 100)), 100));
    }
    entries.push_back(shorts(284, {1}));
    if (dpi_x > 0 && dpi_y > 0) entries.push_back(shorts(296, {2}));  // inches
    entries.push_back(ascii(305, "tp rip"));
    if (channels > 1) entries.push_back(shorts(338, std::vector<std::uint16_t>(static_cast<std::size_t>(channels - 1), 0)));

    // Values that do not fit in an entry go first, each at an even offset, then the directory.
    const std::size_t inline_bytes = big ? 8 : 4;
    std::vector<std::uint8_t> blob;
    if (file_pos & 1) blob.push_back(0);
    std::vector<std::uint64_t> value_at(entries.size(), 0);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (entries[i].bytes.size() <= inline_bytes) continue;
      value_at[i] = file_pos + blob.size();
      blob.insert(blob.end(), entries[i].bytes.begin(), entries[i].bytes.end());
      if (blob.size() & 1) blob.push_back(0);
    }
    const std::uint64_t ifd = file_pos + blob.size();
    put_le(blob, entries.size(), big ? 8 : 2);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const Entry& e = entries[i];
      put_le(blob, e.tag, 2);
      put_le(blob, e.type, 2);
      put_le(blob, e.count, big ? 8 : 4);
      if (e.bytes.size() <= inline_bytes) {
        std::vector<std::uint8_t> v = e.bytes;
        v.resize(inline_bytes, 0);
        blob.insert(blob.end(), v.begin(), v.end());
      } else {
        put_le(blob, value_at[i], big ? 8 : 4);
      }
    }
    put_le(blob, 0, big ? 8 : 4);  // no next directory
    if (auto s = write_bytes(blob.data(), blob.size()); !s) return s;
    // Header: the first directory's offset.
    std::vector<std::uint8_t> head;
    put_le(head, ifd, big ? 8 : 4);
    if (std::fseek(file, big ? 8 : 4, SEEK_SET) != 0 || std::fwrite(head.data(), 1, head.size(), file) != head.size())
      return fail(ErrorCode::kIo, fmt::format("{}: cannot finish the TIFF header", name));
    return {};
  }
};

TiffBandWriter::TiffBandWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

TiffBandWriter::~TiffBandWriter() {
  if (impl_ && impl_->file) std::fclose(impl_->file);
}

Result<std::unique_ptr<TiffBandWriter>> TiffBandWriter::open(const std::filesystem::path& path, int width_px,
                                                             std::int64_t height_px,
                                                             const std::vector<std::string>& channel_names,
                                                             int bits_per_sample, TiffCompression compression,
                                                             double dpi_x, double dpi_y, bool force_bigtiff) {
  const std::string name = path.string();
  if (width_px <= 0 || height_px <= 0 || height_px > 0xffffffffLL || channel_names.empty() || channel_names.size() > 64)
    return fail(ErrorCode::kInvalidArgument, fmt::format("{}: cannot write a {}x{} TIFF with {} channels", name,
                                                         width_px, height_px, channel_names.size()));
  if (bits_per_sample != 1 && bits_per_sample != 2 && bits_per_sample != 4 && bits_per_sample != 8)
    return fail(ErrorCode::kInvalidArgument, fmt::format("{}: bits_per_sample {} is not 1, 2, 4 or 8", name, bits_per_sample));
  auto impl = std::make_unique<Impl>();
  impl->name = name;
  impl->width = width_px;
  impl->height = height_px;
  impl->channels = static_cast<int>(channel_names.size());
  impl->bits = bits_per_sample;
  impl->compression = compression;
  impl->dpi_x = dpi_x;
  impl->dpi_y = dpi_y;
  impl->description = channel_description(channel_names);
  impl->row_bytes = (static_cast<std::size_t>(width_px) * impl->channels * bits_per_sample + 7) / 8;
  impl->rows_per_strip = static_cast<int>(std::clamp<std::size_t>(kTargetStripBytes / impl->row_bytes, 1, kMaxRowsPerStrip));
  impl->strip.resize(impl->row_bytes * impl->rows_per_strip);
  // Raw size decides: compressed data is never much larger than raw.
  impl->big = force_bigtiff || static_cast<double>(impl->row_bytes) * height_px > kBigTiffThresholdBytes;
  impl->file = std::fopen(name.c_str(), "wb");
  if (!impl->file) return fail(ErrorCode::kIo, fmt::format("{}: cannot create file", name));
  // Header with a placeholder directory offset, patched by close().
  std::vector<std::uint8_t> head{'I', 'I'};
  if (impl->big) {
    put_le(head, 43, 2);
    put_le(head, 8, 2);
    put_le(head, 0, 2);
    put_le(head, 0, 8);
  } else {
    put_le(head, 42, 2);
    put_le(head, 0, 4);
  }
  if (auto s = impl->write_bytes(head.data(), head.size()); !s) return std::unexpected(s.error());
  return std::unique_ptr<TiffBandWriter>(new TiffBandWriter(std::move(impl)));
}

Status TiffBandWriter::write_rows(int rows, const std::uint8_t* samples, std::ptrdiff_t row_stride_bytes) {
  Impl& m = *impl_;
  if (m.closed || rows < 0 || m.next_row + rows > m.height)
    return fail(ErrorCode::kIo, fmt::format("{}: rows {}..{} outside the image's {} rows", m.name, m.next_row,
                                            m.next_row + rows - 1, m.height));
  const std::size_t n = static_cast<std::size_t>(m.width) * m.channels;
  const int per_byte = 8 / m.bits, mask = (1 << m.bits) - 1;
  for (int r = 0; r < rows; ++r) {
    const std::uint8_t* src = samples + r * row_stride_bytes;
    std::uint8_t* dst = m.strip.data() + static_cast<std::size_t>(m.strip_rows) * m.row_bytes;
    if (m.bits == 8) {
      std::memcpy(dst, src, n);
    } else {
      // Pack samples MSB first, rows padded to whole bytes.
      std::memset(dst, 0, m.row_bytes);
      for (std::size_t i = 0; i < n; ++i)
        dst[i / per_byte] |= static_cast<std::uint8_t>(std::min<int>(src[i], mask) << (8 - m.bits - (i % per_byte) * m.bits));
    }
    ++m.next_row;
    if (++m.strip_rows == m.rows_per_strip)
      if (auto s = m.flush_strip(); !s) return s;
  }
  return {};
}

Status TiffBandWriter::write_packed_rows(int rows, const std::uint8_t* packed, std::ptrdiff_t row_stride_bytes) {
  Impl& m = *impl_;
  if (m.closed || rows < 0 || m.next_row + rows > m.height)
    return fail(ErrorCode::kIo, fmt::format("{}: rows {}..{} outside the image's {} rows", m.name, m.next_row,
                                            m.next_row + rows - 1, m.height));
  for (int r = 0; r < rows; ++r) {
    std::memcpy(m.strip.data() + static_cast<std::size_t>(m.strip_rows) * m.row_bytes, packed + r * row_stride_bytes, m.row_bytes);
    ++m.next_row;
    if (++m.strip_rows == m.rows_per_strip)
      if (auto s = m.flush_strip(); !s) return s;
  }
  return {};
}

Status TiffBandWriter::close() {
  Impl& m = *impl_;
  if (m.closed) return {};
  m.closed = true;
  if (m.next_row != m.height) {
    std::fclose(m.file);
    m.file = nullptr;
    return fail(ErrorCode::kIo, fmt::format("{}: closed after {} of {} rows", m.name, m.next_row, m.height));
  }
  Status s = m.flush_strip();
  if (s) s = m.write_directory();
  const bool closed_ok = std::fclose(m.file) == 0;
  m.file = nullptr;
  if (!s) return s;
  if (!closed_ok) return fail(ErrorCode::kIo, fmt::format("{}: cannot finish TIFF", m.name));
  return {};
}

}  // namespace tp::rip
