// host/daemon/http/job_file_path.cpp: one component at a time, with lstat, so no symlink or ".."
// anywhere below the output folder leads out of it.
#include "host/daemon/http/job_file_path.h"

#include <sys/stat.h>

#include "host/daemon/http/plain_relative_name.h"

namespace tp::host {

namespace fs = std::filesystem;

Result<fs::path> job_file_path(const fs::path& out_dir, const std::string& name) {
  const std::string shown = "file '" + name + "'";
  auto parts = plain_relative_name(name, "the job's outputs");
  if (!parts) return fail(parts.error());
  fs::path at = out_dir;
  for (size_t i = 0; i < parts->size(); ++i) {
    const std::string& part = (*parts)[i];
    at /= part;
    // lstat: a symlink is refused whatever it points at, even inside the folder.
    struct stat st {};
    if (::lstat(at.c_str(), &st) != 0) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs");
    if (S_ISLNK(st.st_mode)) return fail(ErrorCode::kUnsafePath, shown + ": '" + part + "' is a symlink; not served");
    const bool last = i + 1 == parts->size();
    if (last && !S_ISREG(st.st_mode)) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs (not a file)");
    if (!last && !S_ISDIR(st.st_mode)) return fail(ErrorCode::kJob, "no " + shown + " among the job's outputs");
  }
  return at;
}

}  // namespace tp::host
