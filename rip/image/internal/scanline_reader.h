// rip/image/internal/scanline_reader.h: decodes an image file top to bottom into sRGB RGBA8 rows, the
// engine behind read_image and the streaming ImageFileSource.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <OpenImageIO/filesystem.h>

#include "geometry/common/image.h"
#include "rip/common/error.h"

namespace tp::rip {

/// An open image, decoded in order: embedded ICC profiles converted to sRGB with lcms2, alpha made
/// straight, linear float data sRGB-encoded, no alpha -> 255 (see read_image). EXIF orientation is
/// reported, not applied.
class ScanlineReader {
 public:
  /// Opens `name` (from `proxy` when given). Fails (kImage) naming the file: unreadable, unknown
  /// format, zero or absurd dimensions (width > 2^20), unusable embedded profile.
  [[nodiscard]] static Result<std::unique_ptr<ScanlineReader>> open(const std::string& name,
                                                                     OIIO_NAMESPACE::Filesystem::IOProxy* proxy = nullptr);
  ~ScanlineReader();

  int width_px() const;
  int height_px() const;
  int orientation() const;  ///< EXIF orientation 1..8 (1: as stored)
  int next_row() const;     ///< rows decoded so far

  /// Decodes the next `rows` rows into `out` (rows `stride_px` apart). Fails (kImage) naming the
  /// file and rows on corrupt or truncated data, or when asked past the last row.
  [[nodiscard]] Status read_rows(int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px);

 private:
  struct Impl;
  explicit ScanlineReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::rip
