// host/pipeline/internal/output_files.h: the pipeline's image outputs written checked and
// atomically (temporary name, then rename; host/common/atomic_file.h).
#pragma once

#include <filesystem>

#include "geometry/common/image.h"
#include "host/common/error.h"
#include "rip/image/image_io.h"

namespace tp::host::internal {

/// rip::write_png (with its resolution `dpi`, 0 for none) into a temporary file renamed over `path` on success. Fails (kIo) naming
/// `path` and the system error (ENOSPC); no partial file is left under `path`.
[[nodiscard]] Status write_png_checked(const std::filesystem::path& path, const geometry::ImageRgba8& image,
                                       rip::PngChannels channels = rip::PngChannels::kRgba, double dpi = 0);

}  // namespace tp::host::internal
