// host/daemon/http/plain_relative_name.cpp: splits a file name at '/' and refuses any part that
// is not a plain name, so neither "..", an absolute path nor a Windows separator gets through.
#include "host/daemon/http/plain_relative_name.h"

namespace tp::host {

Result<std::vector<std::string>> plain_relative_name(const std::string& name, const std::string& inside) {
  const std::string shown = "file '" + name + "'";
  if (name.empty() || name.size() > 1024) return fail(ErrorCode::kUnsafePath, shown + ": empty or too long a name");
  if (name.front() == '/') return fail(ErrorCode::kUnsafePath, shown + ": absolute paths are refused");
  std::vector<std::string> parts;
  size_t start = 0;
  for (;;) {
    size_t slash = name.find('/', start);
    if (slash == std::string::npos) slash = name.size();
    std::string part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == ".." || part.find('\0') != std::string::npos ||
        part.find('\\') != std::string::npos)
      return fail(ErrorCode::kUnsafePath, shown + ": '" + part + "' is not a plain name inside " + inside);
    parts.push_back(std::move(part));
    if (slash == name.size()) break;
    start = slash + 1;
  }
  return parts;
}

}  // namespace tp::host
