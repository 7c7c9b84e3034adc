// host/daemon/http/static_file_path.h: resolves a URL path under the console's vendor folder (a
// packaged library such as libjs-three) to a regular file, following only links that stay inside.
#pragma once

#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// The file `name` (URL-decoded, '/' between folders) inside `root`. The name follows the rules of
/// plain_relative_name, as job_file_path's does (no empty, ".", ".." or absolute parts, no NUL or
/// backslash: kUnsafePath), but a
/// symlink on the way is followed when its target lies inside `root` too, as Debian's javascript
/// packages link build/three.module.js to ../three.module.js; a link leading out is kUnsafePath.
/// A missing or non-regular file is kJob ("no file ...").
[[nodiscard]] Result<std::filesystem::path> vendor_file_path(const std::filesystem::path& root,
                                                             const std::string& name);

}  // namespace tp::host
