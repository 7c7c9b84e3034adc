// tests/fuzz/rip_image_fuzz.cpp: fuzzes reading design images from memory (PNG container through
// OpenImageIO, then channel layout, alpha and embedded-profile handling into sRGB).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "rip/image/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto img = tp::rip::read_image_from_memory(std::span<const std::uint8_t>(data, size), "fuzz.png");
  if (!img) {
    if (img.error().message.find("fuzz.png") == std::string::npos) std::abort();  // errors name the file
    return 0;
  }
  if (img->width_px <= 0 || img->height_px <= 0 ||
      img->pixels.size() != static_cast<std::size_t>(img->width_px) * img->height_px)
    std::abort();
  return 0;
}
