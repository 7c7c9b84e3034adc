// simulator/fabric/fabric_tiff.cpp: the fabric TIFF on libtiff (separated, named inks, no alpha).
#include "simulator/fabric/fabric_tiff.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include <tiffio.h>

namespace tp::sim {

namespace {

constexpr std::size_t kTargetStripBytes = 256 * 1024;  ///< strips of about this much raw data
constexpr double kBigTiffThresholdBytes = 3.5e9;       ///< past this a classic TIFF's offsets may overflow

/// libtiff's last message for one file, kept for the error that names it.
int keep_message(TIFF*, void* user_data, const char* module, const char* fmt, va_list ap) {
  char buf[512];
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  *static_cast<std::string*>(user_data) = (module ? std::string(module) + ": " : std::string()) + buf;
  return 1;  // handled: nothing on stderr
}

}  // namespace

struct FabricTiff::Impl {
  std::string name, libtiff_error;
  TIFF* tif = nullptr;
  std::uint64_t height = 0, next_row = 0;
  std::vector<std::uint8_t> row;  ///< the row handed to libtiff, which may encode in place
  bool closed = false;

  [[nodiscard]] std::unexpected<Error> error(const std::string& what) const {
    return fail(ErrorCode::kOutput, name + ": " + what + (libtiff_error.empty() ? "" : " (" + libtiff_error + ")"));
  }
};

FabricTiff::FabricTiff(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

FabricTiff::~FabricTiff() {
  if (impl_ && impl_->tif) TIFFClose(impl_->tif);
}

Result<std::unique_ptr<FabricTiff>> FabricTiff::open(const std::filesystem::path& path, std::uint32_t width_px,
                                                     std::uint64_t height_px, const std::vector<std::string>& inks,
                                                     int dpi_x, int dpi_y) {
  const std::string name = path.string();
  if (width_px == 0 || height_px == 0 || height_px > 0xffffffffULL || inks.empty() || inks.size() > 64)
    return fail(ErrorCode::kInvalidArgument, name + ": cannot write a " + std::to_string(width_px) + "x" +
                                                 std::to_string(height_px) + " fabric with " + std::to_string(inks.size()) + " inks");
  std::string ink_names;  // NUL-separated, one per sample (TIFF 6.0 section 16)
  for (const auto& ink : inks) {
    if (ink.empty()) return fail(ErrorCode::kInvalidArgument, name + ": an ink has no name");
    ink_names += ink + '\0';
  }
  auto impl = std::make_unique<Impl>();
  Impl& m = *impl;
  m.name = name;
  m.height = height_px;
  const std::size_t row_bytes = static_cast<std::size_t>(width_px) * inks.size();
  m.row.resize(row_bytes);
  const bool big = static_cast<double>(row_bytes) * static_cast<double>(height_px) > kBigTiffThresholdBytes;
  TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(opts, keep_message, &m.libtiff_error);
  m.tif = TIFFOpenExt(name.c_str(), big ? "w8" : "w", opts);
  TIFFOpenOptionsFree(opts);
  if (!m.tif) return m.error("cannot create the fabric TIFF");

  const bool cmyk = inks == std::vector<std::string>{"cyan", "magenta", "yellow", "black"};
  std::string description = "tp printsim fabric; channels: ";
  for (std::size_t i = 0; i < inks.size(); ++i) description += (i ? "," : "") + inks[i];
  description += "; samples: summed drop levels";
  const auto rows_per_strip = static_cast<std::uint32_t>(std::max<std::size_t>(1, kTargetStripBytes / row_bytes));
  const bool ok = TIFFSetField(m.tif, TIFFTAG_IMAGEWIDTH, width_px) &&
                  TIFFSetField(m.tif, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(height_px)) &&
                  TIFFSetField(m.tif, TIFFTAG_BITSPERSAMPLE, 8) &&
                  TIFFSetField(m.tif, TIFFTAG_SAMPLESPERPIXEL, static_cast<int>(inks.size())) &&
                  TIFFSetField(m.tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
                  TIFFSetField(m.tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE) &&
                  TIFFSetField(m.tif, TIFFTAG_ZIPQUALITY, 1) &&  // fast: rolls are long, drops compress well anyway
                  TIFFSetField(m.tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_SEPARATED) &&
                  TIFFSetField(m.tif, TIFFTAG_INKSET, cmyk ? INKSET_CMYK : INKSET_MULTIINK) &&
                  TIFFSetField(m.tif, TIFFTAG_NUMBEROFINKS, static_cast<int>(inks.size())) &&
                  TIFFSetField(m.tif, TIFFTAG_INKNAMES, static_cast<int>(ink_names.size()), ink_names.c_str()) &&
                  TIFFSetField(m.tif, TIFFTAG_ROWSPERSTRIP, rows_per_strip) &&
                  TIFFSetField(m.tif, TIFFTAG_XRESOLUTION, static_cast<float>(dpi_x)) &&
                  TIFFSetField(m.tif, TIFFTAG_YRESOLUTION, static_cast<float>(dpi_y)) &&
                  TIFFSetField(m.tif, TIFFTAG_RESOLUTIONUNIT, RESUNIT_INCH) &&
                  TIFFSetField(m.tif, TIFFTAG_IMAGEDESCRIPTION, description.c_str()) &&
                  TIFFSetField(m.tif, TIFFTAG_SOFTWARE, "tp printsim");
  if (!ok) return m.error("cannot set the fabric TIFF's tags");
  return std::unique_ptr<FabricTiff>(new FabricTiff(std::move(impl)));
}

Status FabricTiff::write_row(const std::uint8_t* samples) {
  Impl& m = *impl_;
  if (m.closed || m.next_row >= m.height)
    return fail(ErrorCode::kOutput, m.name + ": row " + std::to_string(m.next_row) + " past the fabric's " +
                                        std::to_string(m.height) + " rows");
  std::copy(samples, samples + m.row.size(), m.row.begin());
  if (TIFFWriteScanline(m.tif, m.row.data(), static_cast<std::uint32_t>(m.next_row), 0) < 0)
    return m.error("cannot write row " + std::to_string(m.next_row));
  ++m.next_row;
  return {};
}

Status FabricTiff::close() {
  Impl& m = *impl_;
  if (m.closed) return {};
  m.closed = true;
  Status s;
  if (m.next_row != m.height)
    s = fail(ErrorCode::kOutput, m.name + ": closed after " + std::to_string(m.next_row) + " of " +
                                     std::to_string(m.height) + " rows");
  else if (!TIFFFlush(m.tif))
    s = m.error("cannot write the fabric TIFF's directory");
  TIFFClose(m.tif);
  m.tif = nullptr;
  return s;
}

}  // namespace tp::sim
