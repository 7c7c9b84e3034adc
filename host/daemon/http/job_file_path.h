// host/daemon/http/job_file_path.h: resolves a file name from GET /api/v1/jobs/{id}/files/{name}
// to a regular file inside that job's output folder, refusing anything that could leave it.
#pragma once

#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// The file `name` (already URL-decoded; '/' separates sub-folders such as "pieces/front.png")
/// inside `out_dir`. Refused (kUnsafePath) when a part is empty, ".", "..", absolute or holds a
/// NUL or backslash, when any part on the way (out_dir's own parts excepted) is a symlink, or
/// when it is not a regular file (kJob: "no file ...").
[[nodiscard]] Result<std::filesystem::path> job_file_path(const std::filesystem::path& out_dir,
                                                          const std::string& name);

}  // namespace tp::host
