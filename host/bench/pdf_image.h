// host/bench/pdf_image.h: a one-page PDF holding one JPEG image, for feeding the same picture to
// Ghostscript.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

/// Writes a PDF whose single page is `width_px` x `height_px` image pixels at `dpi` (page size
/// follows), showing the baseline RGB JPEG `jpeg` (embedded as is, DCTDecode).
/// Fails (kIo) naming the file.
[[nodiscard]] Status write_jpeg_pdf(const std::filesystem::path& path, const std::vector<std::uint8_t>& jpeg,
                                    int width_px, int height_px, double dpi);

}  // namespace tp::rip
