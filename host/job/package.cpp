// host/job/package.cpp: opening job packages and resolving their assets without escaping them.
#include "host/job/package.h"

#include <algorithm>
#include <cstdlib>
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

namespace {

struct LimitField {
  const char* name;
  std::uint64_t PackageLimits::*field;
};
constexpr LimitField kLimitFields[] = {
    {"max_zip_bytes", &PackageLimits::max_total_bytes},      {"max_zip_entry_bytes", &PackageLimits::max_entry_bytes},
    {"max_manifest_bytes", &PackageLimits::max_manifest_bytes}, {"max_asset_bytes", &PackageLimits::max_asset_bytes},
    {"max_layers", &PackageLimits::max_design_layers},       {"max_stroke_points", &PackageLimits::max_stroke_points},
    {"max_source_pixels", &PackageLimits::max_source_pixels}, {"max_memory_bytes", &PackageLimits::max_memory_bytes},
};

}  // namespace

Status set_limit(PackageLimits& limits, const std::string& spec) {
  const auto eq = spec.find('=');
  const std::string name = spec.substr(0, eq);
  std::string known = "max_zip_entries, max_zip_ratio";
  for (const auto& f : kLimitFields) known += std::string(", ") + f.name;
  if (eq == std::string::npos)
    return fail(ErrorCode::kInvalidArgument, "--limit " + spec + ": expected NAME=VALUE (" + known + ")");
  const std::string value = spec.substr(eq + 1);
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !(v > 0) || v > 1e18)
    return fail(ErrorCode::kInvalidArgument, "--limit " + spec + ": the value must be a positive number");
  if (name == "max_zip_ratio") {
    limits.max_ratio = v;
    return {};
  }
  if (name == "max_zip_entries") {
    limits.max_entries = static_cast<std::uint32_t>(std::min(v, 4e9));
    return {};
  }
  for (const auto& f : kLimitFields) {
    if (name == f.name) {
      limits.*f.field = static_cast<std::uint64_t>(v);
      return {};
    }
  }
  return fail(ErrorCode::kInvalidArgument, "--limit " + spec + ": unknown limit \"" + name + "\" (" + known + ")");
}

std::string describe_limits(const PackageLimits& limits) {
  std::string out = "max_zip_entries=" + std::to_string(limits.max_entries) +
                    " max_zip_ratio=" + std::to_string(static_cast<int>(limits.max_ratio));
  for (const auto& f : kLimitFields) out += std::string(" ") + f.name + "=" + std::to_string(limits.*f.field);
  return out;
}

Result<JobPackage> JobPackage::open(const fs::path& path, const fs::path& unpack_dir, const PackageLimits& limits) {
  std::error_code ec;
  JobPackage pkg;
  pkg.source_ = path;
  pkg.limits_ = limits;
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
  // job.json itself must be a plain file of the package: a symlink could point anywhere.
  const auto manifest = fs::symlink_status(pkg.root_ / "job.json", ec);
  if (fs::is_symlink(manifest))
    return fail(ErrorCode::kUnsafePath, path.string() + ": job.json is a symbolic link (it must be a regular file "
                                                        "inside the package)");
  if (!fs::exists(manifest)) return fail(ErrorCode::kJob, path.string() + ": job.json is missing");
  if (!fs::is_regular_file(manifest))
    return fail(ErrorCode::kJob, path.string() + ": job.json is not a regular file");
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
  // Sizes are checked before anything reads the file.
  const auto bytes = fs::file_size(real, ec);
  if (!ec && bytes > limits_.max_asset_bytes)
    return fail(ErrorCode::kValidation, where + "asset \"" + relative + "\" is " + std::to_string(bytes) +
                                            " bytes, over the limit of " + std::to_string(limits_.max_asset_bytes) +
                                            " (max_asset_bytes; raise it with --limit max_asset_bytes=N)");
  return real;
}

}  // namespace tp::host
