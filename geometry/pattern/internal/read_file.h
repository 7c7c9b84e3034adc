// geometry/pattern/internal/read_file.h: reading a whole source file with a size limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "geometry/common/error.h"

namespace tp::geometry::internal {

/// Largest pattern source file read (bytes); bigger files are refused rather than exhausting memory.
inline constexpr std::uintmax_t kMaxPatternFileBytes = 512ull << 20;

/// The file's bytes; kIo naming the path when it is missing, unreadable or too large.
[[nodiscard]] Result<std::string> read_file(const std::filesystem::path& path,
                                            std::uintmax_t max_bytes = kMaxPatternFileBytes);

}  // namespace tp::geometry::internal
