// rip/image/internal/tiff_channels.h: channel (ink) names carried in a TIFF's ImageDescription.
#pragma once

#include <string>
#include <vector>

namespace tp::rip {

/// ImageDescription prefix that carries the channel (ink) names of a separation TIFF.
inline constexpr const char* kChannelsPrefix = "channels=";

/// "channels=cyan,magenta,...".
std::string channel_description(const std::vector<std::string>& channel_names);
/// The names back from a description, or empty if it is not ours or the count differs.
std::vector<std::string> parse_channel_description(const std::string& description, size_t channels);
/// True when the channels are exactly cyan, magenta, yellow, black (TIFF InkSet CMYK); any other
/// ink set is written as InkSet multi-ink with InkNames.
bool is_cmyk_ink_set(const std::vector<std::string>& channel_names);

}  // namespace tp::rip
