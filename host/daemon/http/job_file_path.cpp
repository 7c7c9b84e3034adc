// host/daemon/http/job_file_path.cpp: one component at a time, with lstat, so no symlink or ".."
// anywhere below the output folder leads out of it.
#include "host/daemon/http/job_file_path.h"

#include <sys/stat.h>

namespace tp::host {

namespace fs = std::filesystem;

Result<fs::path> job_file_path(const fs::path& out_dir, const std::string& name) {
  const std::string shown = "file '" + name + "'";
  if (name.empty() || name.size() > 1024) return fail(ErrorCode::kUnsafePath, shown + ": empty or too long a name");
  if (name.front() == '/') return fail(ErrorCode::kUnsafePath, shown + ": absolute paths are refused");
  fs::path at = out_dir;
  size_t start = 0;
  while (start <= name.size()) {
    size_t slash = name.find('/', start);
    if (slash == std::string::npos) slash = name.size();
    const std::string part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == ".." || part.find('\0') != std::string::npos ||
        part.find('\\') != std::string::npos)
      return fail(ErrorCode::kUnsafePath, shown + ": '" + part + "' is not a plain name inside the job's outputs");
    at /= part;
    // lstat: a symlink is refused whatever it points at, even inside the folder.
    struct stat st {};
    if (::lstat(at.c_str(), &st) != 0) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs");
    if (S_ISLNK(st.st_mode)) return fail(ErrorCode::kUnsafePath, shown + ": '" + part + "' is a symlink; not served");
    const bool last = slash == name.size();
    if (last && !S_ISREG(st.st_mode)) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs (not a file)");
    if (!last && !S_ISDIR(st.st_mode)) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs");
    start = slash + 1;
    if (last) break;
  }
  return at;
}

}  // namespace tp::host
