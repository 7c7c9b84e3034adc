// tests/support/image_files.h: image files written with OpenImageIO exactly as a test specifies them.
#pragma once

#include <filesystem>

#include <OpenImageIO/imageio.h>

namespace tp::test {

/// Writes `data` (laid out as `spec` says) to `path`, in the format of its extension, with the
/// spec's attributes (profiles, orientation, ...). Fails the calling test on any error.
void write_raw_image(const std::filesystem::path& path, const OIIO_NAMESPACE::ImageSpec& spec, const void* data);

/// A 3 x 2 RGB8 TIFF whose grey pixels are 0, 10, ... 50 in storage order, tagged EXIF orientation 6
/// ("rotate 90 degrees clockwise to display"): displayed it is 2 x 3, top row 30, 0.
void write_oriented_tiff(const std::filesystem::path& path);

}  // namespace tp::test
