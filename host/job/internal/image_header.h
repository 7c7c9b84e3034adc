// host/job/internal/image_header.h: an image file's pixel dimensions from its header alone
// (PNG, JPEG), so a job's source pixels are counted before any image is decoded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

namespace tp::host::internal {

struct ImageDimensions {
  std::int64_t width_px = 0;
  std::int64_t height_px = 0;
};

/// Width and height from a PNG IHDR or a JPEG SOF marker; nullopt for other formats or an
/// unreadable header (the image reader reports those when it decodes).
std::optional<ImageDimensions> read_image_dimensions(const std::filesystem::path& path);

}  // namespace tp::host::internal
