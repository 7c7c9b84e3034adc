// host/job/internal/image_header.cpp: PNG and JPEG header sniffing, bounded reads only.
#include "host/job/internal/image_header.h"

#include <array>
#include <fstream>

namespace tp::host::internal {

namespace {

std::uint32_t be32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

std::optional<ImageDimensions> jpeg_dimensions(std::ifstream& in) {
  // Walk the marker segments up to a start-of-frame; give up after 1 MiB of headers.
  std::streamoff pos = 2;
  for (int guard = 0; guard < 4096 && pos < (1 << 20); ++guard) {
    unsigned char m[4];
    in.seekg(pos);
    if (!in.read(reinterpret_cast<char*>(m), 4) || m[0] != 0xFF) return std::nullopt;
    const unsigned marker = m[1];
    const unsigned len = (unsigned{m[2]} << 8) | m[3];
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      unsigned char f[5];
      if (!in.read(reinterpret_cast<char*>(f), 5)) return std::nullopt;
      return ImageDimensions{(std::int64_t{f[3]} << 8) | f[4], (std::int64_t{f[1]} << 8) | f[2]};
    }
    if (len < 2) return std::nullopt;
    pos += 2 + len;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ImageDimensions> read_image_dimensions(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> h{};
  if (!in.read(reinterpret_cast<char*>(h.data()), 24)) {
    in.clear();
  }
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (std::equal(kPng, kPng + 8, h.begin()) && h[12] == 'I' && h[13] == 'H' && h[14] == 'D' && h[15] == 'R')
    return ImageDimensions{be32(&h[16]), be32(&h[20])};
  if (h[0] == 0xFF && h[1] == 0xD8) {
    in.clear();
    return jpeg_dimensions(in);
  }
  return std::nullopt;
}

}  // namespace tp::host::internal
