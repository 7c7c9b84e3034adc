// rip/render/image_file_source.h: an image file printed pixel for pixel, decoded on a thread of its
// own while the RIP colours and screens the rows already decoded (Ghostscript comparison, test
// prints and calibration charts straight from a file). Memory holds a window of rows, not the image.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "rip/common/error.h"
#include "rip/render/band_source.h"

namespace tp::rip {

/// Band source over an image file: print column x, row y is image pixel (x, y) after EXIF
/// orientation. Rows are decoded in order on a decoder thread into a ring of `window_rows` rows;
/// render_rows waits for its rows and frees them once copied. The RIP asks for rows at most one
/// band ahead of the lowest row not yet copied, so `window_rows` must exceed the band height
/// (a request further ahead fails through status() rather than wait forever). An oriented image
/// (EXIF orientation other than 1) cannot be turned row by row: it is read whole instead.
class ImageFileSource final : public BandSource {
 public:
  /// Opens the file and starts decoding. Fails (kImage) naming the file as read_image does, or
  /// (kInvalidArgument) when window_rows < 2 * kRenderTileRows.
  [[nodiscard]] static Result<std::unique_ptr<ImageFileSource>> open(const std::filesystem::path& path, int window_rows);
  ~ImageFileSource() override;
  ImageFileSource(const ImageFileSource&) = delete;
  ImageFileSource& operator=(const ImageFileSource&) = delete;

  int width_px() const override;
  std::int64_t height_px() const override;
  void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const override;
  /// The decoder's error (corrupt or truncated data, naming the file and rows), or a request
  /// outside the window.
  [[nodiscard]] Status status() const override;

 private:
  struct Impl;
  explicit ImageFileSource(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::rip
