// rip/image/tiff_channels.cpp: formats and parses the channel list of separation TIFFs.
#include "rip/image/internal/tiff_channels.h"

namespace tp::rip {

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

}  // namespace tp::rip
