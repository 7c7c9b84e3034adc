// rip/image/tiff_band_writer.cpp: the streaming separation TIFF / BigTIFF writer on libtiff: strips
// go to disk as rows arrive (PackBits, Deflate or raw), the directory when the file closes.
//
// Separations are tagged as their format means them: Photometric Separated, InkSet CMYK when the
// channels are cyan, magenta, yellow, black in that order, otherwise InkSet multi-ink with one
// InkNames entry per channel; no ExtraSamples, so no reader takes a channel for alpha.
#include "rip/image/tiff_band_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstring>

#include <spdlog/fmt/fmt.h>
#include <tiffio.h>

#include "rip/image/internal/tiff_channels.h"

namespace tp::rip {

namespace {

constexpr std::size_t kTargetStripBytes = 256 * 1024;  ///< strips of about this much raw data
constexpr int kMaxRowsPerStrip = 256;
constexpr double kBigTiffThresholdBytes = 3.5e9;       ///< past this a classic TIFF's offsets may overflow

/// libtiff's messages for one file, kept for the error that names it.
int keep_message(TIFF*, void* user_data, const char* module, const char* fmt, va_list ap) {
  char buf[512];
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  auto* out = static_cast<std::string*>(user_data);
  *out = (module ? std::string(module) + ": " : std::string()) + buf;
  return 1;  // handled: nothing on stderr
}

}  // namespace

bool is_cmyk_ink_set(const std::vector<std::string>& channel_names) {
  return channel_names == std::vector<std::string>{"cyan", "magenta", "yellow", "black"};
}

struct TiffBandWriter::Impl {
  std::string name;
  std::string libtiff_error;
  TIFF* tif = nullptr;
  int width = 0, channels = 0, bits = 8;
  std::int64_t height = 0, next_row = 0;
  int rows_per_strip = 1;
  std::size_t row_bytes = 0;        ///< packed bytes of one row (all samples)
  std::vector<std::uint8_t> strip;  ///< packed rows of the strip being filled
  int strip_rows = 0;
  std::uint32_t strip_index = 0;
  bool closed = false;

  [[nodiscard]] std::unexpected<Error> io_error(const std::string& what) const {
    return fail(ErrorCode::kIo, fmt::format("{}: {}{}", name, what, libtiff_error.empty() ? "" : " (" + libtiff_error + ")"));
  }

  /// Hands the filled strip to libtiff, which compresses and writes it.
  Status flush_strip() {
    if (strip_rows == 0) return {};
    const auto raw = static_cast<tmsize_t>(static_cast<std::size_t>(strip_rows) * row_bytes);
    if (TIFFWriteEncodedStrip(tif, strip_index, strip.data(), raw) < 0)
      return io_error(fmt::format("cannot write strip {} (rows {}..{})", strip_index, next_row - strip_rows, next_row - 1));
    ++strip_index;
    strip_rows = 0;
    return {};
  }
};

TiffBandWriter::TiffBandWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

TiffBandWriter::~TiffBandWriter() {
  if (impl_ && impl_->tif) TIFFClose(impl_->tif);
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
  for (const auto& ink : channel_names)
    if (ink.empty() || ink.find('\0') != std::string::npos || ink.find(',') != std::string::npos)
      return fail(ErrorCode::kInvalidArgument, fmt::format("{}: channel name '{}' is empty or holds a comma", name, ink));
  auto impl = std::make_unique<Impl>();
  Impl& m = *impl;
  m.name = name;
  m.width = width_px;
  m.height = height_px;
  m.channels = static_cast<int>(channel_names.size());
  m.bits = bits_per_sample;
  m.row_bytes = (static_cast<std::size_t>(width_px) * m.channels * bits_per_sample + 7) / 8;
  m.rows_per_strip = static_cast<int>(std::clamp<std::size_t>(kTargetStripBytes / m.row_bytes, 1, kMaxRowsPerStrip));
  m.strip.resize(m.row_bytes * m.rows_per_strip);
  // Raw size decides: compressed data is never much larger than raw.
  const bool big = force_bigtiff || static_cast<double>(m.row_bytes) * height_px > kBigTiffThresholdBytes;

  TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(opts, keep_message, &m.libtiff_error);
  m.tif = TIFFOpenExt(name.c_str(), big ? "w8" : "w", opts);
  TIFFOpenOptionsFree(opts);
  if (!m.tif) return m.io_error("cannot create file");

  // Ink names: NUL-separated, one per channel (TIFF 6.0 section 16).
  std::string ink_names;
  for (const auto& ink : channel_names) ink_names += ink + '\0';
  const bool cmyk = is_cmyk_ink_set(channel_names);
  const std::uint16_t comp = compression == TiffCompression::kPackBits ? COMPRESSION_PACKBITS
                             : compression == TiffCompression::kDeflate ? COMPRESSION_ADOBE_DEFLATE
                                                                        : COMPRESSION_NONE;
  const std::string description = channel_description(channel_names);
  bool ok = TIFFSetField(m.tif, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(width_px)) &&
            TIFFSetField(m.tif, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(height_px)) &&
            TIFFSetField(m.tif, TIFFTAG_BITSPERSAMPLE, static_cast<std::uint16_t>(bits_per_sample)) &&
            TIFFSetField(m.tif, TIFFTAG_SAMPLESPERPIXEL, static_cast<std::uint16_t>(m.channels)) &&
            TIFFSetField(m.tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
            TIFFSetField(m.tif, TIFFTAG_COMPRESSION, comp) &&
            TIFFSetField(m.tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_SEPARATED) &&
            TIFFSetField(m.tif, TIFFTAG_INKSET, cmyk ? INKSET_CMYK : INKSET_MULTIINK) &&
            TIFFSetField(m.tif, TIFFTAG_NUMBEROFINKS, static_cast<std::uint16_t>(m.channels)) &&
            TIFFSetField(m.tif, TIFFTAG_INKNAMES, static_cast<int>(ink_names.size()), ink_names.c_str()) &&
            TIFFSetField(m.tif, TIFFTAG_ROWSPERSTRIP, static_cast<std::uint32_t>(m.rows_per_strip)) &&
            TIFFSetField(m.tif, TIFFTAG_IMAGEDESCRIPTION, description.c_str()) &&
            TIFFSetField(m.tif, TIFFTAG_SOFTWARE, "tp rip");
  if (ok && comp == COMPRESSION_ADOBE_DEFLATE) ok = TIFFSetField(m.tif, TIFFTAG_ZIPQUALITY, 1);  // fast: rolls are long
  if (ok && dpi_x > 0 && dpi_y > 0)
    ok = TIFFSetField(m.tif, TIFFTAG_XRESOLUTION, static_cast<float>(dpi_x)) &&
         TIFFSetField(m.tif, TIFFTAG_YRESOLUTION, static_cast<float>(dpi_y)) &&
         TIFFSetField(m.tif, TIFFTAG_RESOLUTIONUNIT, RESUNIT_INCH);
  if (!ok) return m.io_error("cannot set the TIFF tags");
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
    TIFFClose(m.tif);
    m.tif = nullptr;
    return fail(ErrorCode::kIo, fmt::format("{}: closed after {} of {} rows", m.name, m.next_row, m.height));
  }
  Status s = m.flush_strip();
  // TIFFClose writes the directory but reports nothing; flush first so a failure is seen.
  if (s && !TIFFFlush(m.tif)) s = m.io_error("cannot write the TIFF directory");
  TIFFClose(m.tif);
  m.tif = nullptr;
  return s;
}

}  // namespace tp::rip
