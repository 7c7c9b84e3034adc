// host/pipeline/internal/output_files.cpp: checked PNG outputs.
#include "host/pipeline/internal/output_files.h"

#include "host/common/atomic_file.h"

namespace tp::host::internal {

Status write_png_checked(const std::filesystem::path& path, const geometry::ImageRgba8& image,
                         rip::PngChannels channels, double dpi) {
  return write_via_temp(path, [&](const std::filesystem::path& tmp) -> Status {
    if (auto st = rip::write_png(tmp, image, channels, dpi); !st) return fail(ErrorCode::kIo, st.error().message);
    return {};
  });
}

}  // namespace tp::host::internal
