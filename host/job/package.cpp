// host/job/package.cpp: opening job packages and resolving their assets without escaping them.
#include "host/job/package.h"

#include <system_error>

namespace tp::host {

namespace fs = std::filesystem;

Status check_relative_path(const std::string& relative) {
  if (relative.empty()) return fail(ErrorCode::kUnsafePath, "empty path");
  if (relative.find('\0') != std::string::npos) return fail(ErrorCode::kUnsafePath, "path contains a NUL byte");
  if (relative.find('\\') != std::string::npos)
    return fail(ErrorCode::kUnsafePath, "path \"" + relative + "\" contains a backslash (use /)");
  fs::path p(relative);
  if (p.is_absolute() || relative[0] == '/')
    return fail(ErrorCode::kUnsafePath, "absolute path \"" + relative + "\" (paths are relative to the package)");
  for (const auto& part : p) {
    if (part == "..")
      return fail(ErrorCode::kUnsafePath, "path \"" + relative + "\" leaves the package (\"..\")");
  }
  return {};
}

Result<JobPackage> JobPackage::open(const fs::path& path, const fs::path& unpack_dir, const PackageLimits& limits) {
  std::error_code ec;
  JobPackage pkg;
  pkg.source_ = path;
  if (fs::is_directory(path, ec)) {
    pkg.root_ = fs::canonical(path, ec);
    if (ec) return fail(ErrorCode::kJob, path.string() + ": " + ec.message());
  } else if (fs::is_regular_file(path, ec)) {
    if (path.extension() != ".zip")
      return fail(ErrorCode::kJob, path.string() + ": a job is a folder with job.json or a .zip of one");
    if (fs::exists(unpack_dir) && !fs::is_empty(unpack_dir, ec))
      return fail(ErrorCode::kIo, unpack_dir.string() + ": unpack folder is not empty");
    fs::create_directories(unpack_dir, ec);
    if (ec) return fail(ErrorCode::kIo, unpack_dir.string() + ": " + ec.message());
    if (auto st = unpack_zip(path, unpack_dir, limits); !st) return std::unexpected(st.error());
    // A zip may hold job.json at its top or inside one top-level folder.
    fs::path root = unpack_dir;
    if (!fs::exists(root / "job.json")) {
      int dirs = 0;
      fs::path only;
      for (const auto& e : fs::directory_iterator(unpack_dir)) {
        if (e.is_directory()) { ++dirs; only = e.path(); }
      }
      if (dirs == 1 && fs::exists(only / "job.json")) root = only;
    }
    pkg.root_ = fs::canonical(root, ec);
  } else {
    return fail(ErrorCode::kJob, path.string() + ": no such job (expected a folder or a .zip)");
  }
  if (!fs::is_regular_file(pkg.root_ / "job.json"))
    return fail(ErrorCode::kJob, path.string() + ": job.json is missing");
  return pkg;
}

Result<fs::path> JobPackage::resolve_asset(const std::string& relative, const std::string& pointer) const {
  const std::string where = "job.json: " + pointer + ": ";
  if (auto st = check_relative_path(relative); !st) return std::unexpected(st.error().with_context(where.substr(0, where.size() - 2)));
  std::error_code ec;
  fs::path full = root_ / relative;
  if (!fs::exists(full, ec))
    return fail(ErrorCode::kValidation, where + "asset \"" + relative + "\" is missing from the package");
  // Follow symlinks, then insist the target is still inside the package.
  fs::path real = fs::canonical(full, ec);
  if (ec) return fail(ErrorCode::kValidation, where + "asset \"" + relative + "\": " + ec.message());
  auto rel = real.lexically_relative(root_);
  if (rel.empty() || *rel.begin() == "..")
    return fail(ErrorCode::kUnsafePath, where + "asset \"" + relative + "\" is a link that leaves the package");
  if (!fs::is_regular_file(real, ec))
    return fail(ErrorCode::kValidation, where + "asset \"" + relative + "\" is not a regular file");
  return real;
}

}  // namespace tp::host
