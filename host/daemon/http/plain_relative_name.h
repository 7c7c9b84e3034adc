// host/daemon/http/plain_relative_name.h: the one check of a URL file name's parts before any
// file route (job outputs, the console's vendor libraries) looks at the disk.
#pragma once

#include <string>
#include <vector>

#include "host/common/error.h"

namespace tp::host {

/// The parts of `name` (URL-decoded, '/' between folders), each a plain name: kUnsafePath when
/// `name` is empty, longer than 1024 bytes or absolute, or a part is empty, ".", ".." or holds a
/// NUL or backslash. Messages name the file and say it is not a plain name inside `inside` (for
/// example "the job's outputs").
[[nodiscard]] Result<std::vector<std::string>> plain_relative_name(const std::string& name, const std::string& inside);

}  // namespace tp::host
