// rip/image/tiff_band_writer.h: writes a TIFF band by band, so separations of a long roll never sit
// in memory whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "rip/common/error.h"
#include "rip/image/image_io.h"

namespace tp::rip {

/// A TIFF (BigTIFF when the raw data could pass 3.5 GB) open for writing top to bottom with libtiff:
/// strips are compressed and written as rows arrive, the directory when it closes. Separated
/// (Photometric 5: a sample is the ink amount), InkSet CMYK when the channels are cyan, magenta,
/// yellow, black in that order and multi-ink otherwise, one InkNames entry per channel, no
/// ExtraSamples; the names also in the ImageDescription ("channels=cyan,magenta,...").
/// Samples given to write_rows are 8-bit, interleaved per pixel, holding 0 .. 2^bits - 1.
class TiffBandWriter {
 public:
  /// Opens `path` for a width x height image with the named channels, recording the resolution
  /// when dpi_x and dpi_y are positive; BigTIFF when large or `force_bigtiff`. Fails (kIo) naming the
  /// file, (kInvalidArgument) like write_tiff or for an empty channel name or one holding a comma.
  [[nodiscard]] static Result<std::unique_ptr<TiffBandWriter>> open(const std::filesystem::path& path, int width_px,
                                                                    std::int64_t height_px,
                                                                    const std::vector<std::string>& channel_names,
                                                                    int bits_per_sample, TiffCompression compression,
                                                                    double dpi_x = 0, double dpi_y = 0,
                                                                    bool force_bigtiff = false);
  ~TiffBandWriter();

  /// Appends `rows` rows (the next ones in order), rows `row_stride_bytes` apart.
  /// Fails (kIo) naming the file and rows.
  [[nodiscard]] Status write_rows(int rows, const std::uint8_t* samples, std::ptrdiff_t row_stride_bytes);
  /// Appends rows already packed as the file stores them: samples interleaved, `bits_per_sample`
  /// each, MSB first, each row padded to a whole byte (how screened rows are kept in memory).
  [[nodiscard]] Status write_packed_rows(int rows, const std::uint8_t* packed, std::ptrdiff_t row_stride_bytes);
  /// Finishes the file; fails (kIo) if rows are missing or the write fails.
  [[nodiscard]] Status close();

 private:
  struct Impl;
  explicit TiffBandWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::rip
