// rip/image/image_io.h: reading design images into the sRGB working space and writing PNG and
// multi-channel TIFF files (OpenImageIO and lcms2 stay inside rip/).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/common/image.h"
#include "rip/common/error.h"

namespace tp::rip {

/// Largest image read_image accepts, in pixels (1 GiB of RGBA8): a guard against hostile headers.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 28;

/// Reads an image file (any format OpenImageIO reads: PNG, JPEG, TIFF, EXR, ...) into straight-alpha
/// RGBA8 in the sRGB working space.
///
/// An embedded ICC profile (RGB, grey or CMYK) is converted to sRGB with lcms2 (relative
/// colorimetric with black point compensation); without one, RGB is taken as sRGB, grey as sRGB
/// grey, linear float data (EXR) is sRGB-encoded. Premultiplied alpha is un-premultiplied, the
/// EXIF orientation is applied, and images without alpha get alpha 255. `source` of the result is
/// the path.
/// Fails (kImage) naming the file: unreadable or unknown format, truncated data, zero or
/// oversized dimensions (> kMaxImagePixels), an unusable embedded profile.
[[nodiscard]] Result<geometry::ImageRgba8> read_image(const std::filesystem::path& path);

/// Same as read_image, from an in-memory file; `name` (with the format's extension, e.g.
/// "design.png") selects the reader and names the image in errors.
[[nodiscard]] Result<geometry::ImageRgba8> read_image_from_memory(std::span<const std::uint8_t> bytes,
                                                                  std::string_view name);

/// How write_png stores pixels.
enum class PngChannels {
  kRgba,          ///< straight alpha kept (alpha 0 = unprinted fabric)
  kRgbOverWhite,  ///< composited over white fabric, no alpha channel
};

/// Writes an 8-bit sRGB PNG with a pHYs chunk: `dpi` pixels per inch each way (stored per metre),
/// or, for images with no physical size (dpi 0: renders, previews), square pixels of unknown
/// size. Fails (kIo) naming the file when it cannot be created or written, and
/// (kInvalidArgument) when the image's pixel count does not match its dimensions.
[[nodiscard]] Status write_png(const std::filesystem::path& path, const geometry::ImageRgba8& image,
                               PngChannels channels = PngChannels::kRgba, double dpi = 0);

/// The PNG write_png would write, in memory, at zlib `compression_level` (0..9; write_png uses
/// OIIO's default, 6): a live preview spends less time packing what it sends at once. Fails
/// (kIo) naming `name` when the encoder refuses, (kInvalidArgument) like write_png.
[[nodiscard]] Result<std::string> encode_png(const geometry::ImageRgba8& image, PngChannels channels, double dpi,
                                             int compression_level, const std::string& name = "image.png");

/// Writes a baseline 8-bit sRGB JPEG at `quality` (1..100), composited over white fabric.
/// Fails (kIo) naming the file, (kInvalidArgument) like write_png.
[[nodiscard]] Status write_jpeg(const std::filesystem::path& path, const geometry::ImageRgba8& image, int quality = 90);

/// An image of any number of named 8-bit channels, interleaved (pixel-major), row 0 on top.
struct ChannelImage8 {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::string> channel_names;  ///< e.g. {"cyan", "magenta", "yellow", "black"}
  std::vector<std::uint8_t> samples;       ///< width_px * height_px * channel_names.size()
};

/// TIFF compression for written separations.
enum class TiffCompression { kNone, kPackBits, kDeflate };

/// Writes a multi-channel separated TIFF (one sample per channel, no alpha, a sample is the amount
/// of that channel; InkSet and InkNames as TiffBandWriter writes them). `bits_per_sample` is 8, or 1, 2 or 4 for
/// screened data, in which case the samples hold values 0 .. 2^bits - 1. Fails (kIo) naming the file,
/// (kInvalidArgument) on inconsistent sizes or an unsupported bit depth.
[[nodiscard]] Status write_tiff(const std::filesystem::path& path, const ChannelImage8& image, int bits_per_sample = 8,
                                TiffCompression compression = TiffCompression::kDeflate);

/// Reads every channel of any image as 8-bit interleaved samples (for tests and tools that check
/// separations); values are the file's own (no colour conversion). Fails (kImage) naming the file.
[[nodiscard]] Result<ChannelImage8> read_channels8(const std::filesystem::path& path);

}  // namespace tp::rip
