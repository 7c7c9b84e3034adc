// host/daemon/http/static_file_path.cpp: name checks first, then the canonical target must stay
// inside the canonical root, so neither ".." nor a link can reach a file beside the library.
#include "host/daemon/http/static_file_path.h"

namespace tp::host {

namespace fs = std::filesystem;

Result<fs::path> vendor_file_path(const fs::path& root, const std::string& name) {
  const std::string shown = "file '" + name + "'";
  if (name.empty() || name.size() > 1024) return fail(ErrorCode::kUnsafePath, shown + ": empty or too long a name");
  if (name.front() == '/') return fail(ErrorCode::kUnsafePath, shown + ": absolute paths are refused");
  size_t start = 0;
  while (start <= name.size()) {
    size_t slash = name.find('/', start);
    if (slash == std::string::npos) slash = name.size();
    const std::string part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == ".." || part.find('\0') != std::string::npos ||
        part.find('\\') != std::string::npos)
      return fail(ErrorCode::kUnsafePath, shown + ": '" + part + "' is not a plain name inside " + root.string());
    start = slash + 1;
    if (slash == name.size()) break;
  }
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
