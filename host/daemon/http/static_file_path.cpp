// host/daemon/http/static_file_path.cpp: name checks first, then the canonical target must stay
// inside the canonical root, so neither ".." nor a link can reach a file beside the library.
#include "host/daemon/http/static_file_path.h"

#include "host/daemon/http/plain_relative_name.h"

namespace tp::host {

namespace fs = std::filesystem;

Result<fs::path> vendor_file_path(const fs::path& root, const std::string& name) {
  const std::string shown = "file '" + name + "'";
  if (auto parts = plain_relative_name(name, root.string()); !parts) return fail(parts.error());
  std::error_code ec;
  const fs::path base = fs::canonical(root, ec);
  if (ec) return fail(ErrorCode::kJob, "no " + shown + ": " + root.string() + " is missing");
  const fs::path target = fs::canonical(base / name, ec);
  if (ec) return fail(ErrorCode::kJob, "no " + shown + " in " + root.string());
  // Inside means below the root: the relative path must not begin with "..".
  const fs::path rel = target.lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..")
    return fail(ErrorCode::kUnsafePath, shown + ": a link leads out of " + root.string());
  if (!fs::is_regular_file(target, ec))
    return fail(ErrorCode::kJob, "no " + shown + " in " + root.string() + " (not a file)");
  return target;
}

}  // namespace tp::host
