// host/common/atomic_file.h: checked output files: written under a temporary name, synced, renamed.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

#include "host/common/error.h"

namespace tp::host {

/// The temporary name an output is written under before it is renamed into place
/// ("<dir>/.<stem>.tmp-<pid><ext>"): hidden, so hot-folder and report readers skip it, and the
/// extension kept last so writers that choose a format by it still do.
std::filesystem::path temp_path_for(const std::filesystem::path& path);

/// Writes `bytes` to `path`: into temp_path_for(path), every write checked, fsync'd, then renamed
/// over `path`, so a reader sees the old file or the whole new one, never a truncated one. Fails
/// (kIo) naming the path and the system error ("out/cut.dxf: No space left on device (ENOSPC)");
/// the temporary file is removed on failure. `mode` is applied to the new file.
[[nodiscard]] Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes, unsigned mode = 0644);

/// Runs `writer` on temp_path_for(path), and renames the result over `path` when it succeeds and
/// the file is not empty; removes the temporary file otherwise. For writers in other layers that
/// take a path (PNG, TIFF). The writer's error is returned with `path` named.
[[nodiscard]] Status write_via_temp(const std::filesystem::path& path,
                                    const std::function<Status(const std::filesystem::path& temp)>& writer);

/// "Name (ENAME)" of an errno value, e.g. "No space left on device (ENOSPC)".
std::string errno_text(int error_number);

/// Test hook: when set, write_file_atomic behaves as if the disk filled up after `bytes` more
/// bytes (ENOSPC). Negative = off. Not thread-safe; for unit tests only.
void set_write_budget_for_tests(long long bytes);

}  // namespace tp::host
