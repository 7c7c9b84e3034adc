// rip/image/tiff_spec.cpp: builds the TIFF header description for separations.
#include "rip/image/internal/tiff_spec.h"

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

namespace OIIO = OIIO_NAMESPACE;

std::string channel_description(const std::vector<std::string>& channel_names) {
  std::string d = kChannelsPrefix;
  for (size_t i = 0; i < channel_names.size(); ++i) d += (i ? "," : "") + channel_names[i];
  return d;
}

std::vector<std::string> parse_channel_description(const std::string& description, size_t channels) {
  if (description.rfind(kChannelsPrefix, 0) != 0) return {};
  std::vector<std::string> names;
  size_t pos = std::string(kChannelsPrefix).size();
  while (pos <= description.size()) {
    size_t comma = description.find(',', pos);
    if (comma == std::string::npos) comma = description.size();
    names.push_back(description.substr(pos, comma - pos));
    pos = comma + 1;
  }
  if (names.size() != channels) return {};
  return names;
}

Result<OIIO::ImageSpec> tiff_spec(const std::filesystem::path& path, int width_px, int height_px,
                                  const std::vector<std::string>& channel_names, int bits_per_sample,
                                  TiffCompression compression) {
  const std::string name = path.string();
  if (width_px <= 0 || height_px <= 0 || channel_names.empty() || channel_names.size() > 64)
    return fail(ErrorCode::kInvalidArgument, fmt::format("{}: cannot write a {}x{} TIFF with {} channels", name,
                                                         width_px, height_px, channel_names.size()));
  if (bits_per_sample != 1 && bits_per_sample != 2 && bits_per_sample != 4 && bits_per_sample != 8)
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("{}: bits_per_sample {} is not 1, 2, 4 or 8", name, bits_per_sample));
  OIIO::ImageSpec spec(width_px, height_px, static_cast<int>(channel_names.size()), OIIO::TypeDesc::UINT8);
  spec.channelnames = channel_names;
  spec.alpha_channel = -1;
  // TIFF has no channel names: keep ink names where read_channels8 (and people) find them.
  spec.attribute("ImageDescription", channel_description(channel_names));
  if (bits_per_sample < 8) spec.attribute("oiio:BitsPerSample", bits_per_sample);
  switch (compression) {
    case TiffCompression::kNone: spec.attribute("compression", "none"); break;
    case TiffCompression::kPackBits: spec.attribute("compression", "packbits"); break;
    case TiffCompression::kDeflate: spec.attribute("compression", "zip"); break;
  }
  // Classic TIFF offsets are 32-bit: long rolls at print resolution need BigTIFF.
  const double bytes = static_cast<double>(width_px) * height_px * channel_names.size() * bits_per_sample / 8.0;
  if (bytes > 3.5e9) spec.attribute("tiff:bigtiff", 1);
  return spec;
}

}  // namespace tp::rip
