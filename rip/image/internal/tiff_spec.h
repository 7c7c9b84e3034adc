// rip/image/internal/tiff_spec.h: the OpenImageIO spec for a separation TIFF (shared by the whole-image
// and band-by-band writers).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "rip/common/error.h"
#include "rip/image/image_io.h"

namespace tp::rip {

/// ImageDescription prefix that carries the channel (ink) names of a separation TIFF.
inline constexpr const char* kChannelsPrefix = "channels=";

/// "channels=cyan,magenta,...".
std::string channel_description(const std::vector<std::string>& channel_names);
/// The names back from a description, or empty if it is not ours or the count differs.
std::vector<std::string> parse_channel_description(const std::string& description, size_t channels);

/// Spec for a min-is-black TIFF with the given channels; BigTIFF when the data could pass 4 GiB.
/// Fails (kInvalidArgument) naming the file on bad sizes, no channels or an unsupported bit depth.
Result<OIIO_NAMESPACE::ImageSpec> tiff_spec(const std::filesystem::path& path, int width_px, int height_px,
                                            const std::vector<std::string>& channel_names, int bits_per_sample,
                                            TiffCompression compression);

}  // namespace tp::rip
