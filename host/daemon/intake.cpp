// host/daemon/intake.cpp: package checks and spool moves shared by the hot folder and the socket.
#include "host/daemon/intake.h"

#include <unistd.h>

#include "host/common/sha256.h"
#include "host/job/manifest.h"
#include "host/job/package.h"

namespace tp::host {

namespace fs = std::filesystem;

Result<CheckedPackage> check_package(const fs::path& path, const fs::path& scratch_dir, const PackageLimits& limits,
                                     const JobCheck& check) {
  fs::path unpack = scratch_dir / ("check-" + std::to_string(::getpid()) + "-" + path.filename().string());
  std::error_code ec;
  fs::remove_all(unpack, ec);
  Result<CheckedPackage> out = CheckedPackage{};
  if (auto pkg = JobPackage::open(path, unpack, limits); !pkg) {
    out = std::unexpected(pkg.error());
  } else if (auto job = load_job(*pkg); !job) {
    out = std::unexpected(job.error());
  } else if (auto st = check ? check(*job) : Status{}; !st) {
    out = std::unexpected(st.error());
  } else if (auto hash = package_hash(path); !hash) {
    out = std::unexpected(hash.error());
  } else {
    out = CheckedPackage{job->name, path, *hash};
  }
  fs::remove_all(unpack, ec);
  return out;
}

Result<Job> open_spooled_job(const fs::path& package, const PackageLimits& limits) {
  fs::path unpack = package;
  unpack += ".unpacked";
  std::error_code ec;
  if (!fs::is_directory(package)) fs::remove_all(unpack, ec);
  auto pkg = JobPackage::open(package, unpack, limits);
  if (!pkg) return std::unexpected(pkg.error());
  return load_job(*pkg);
}

void remove_spooled(const fs::path& package) {
  std::error_code ec;
  fs::path unpacked = package;
  unpacked += ".unpacked";
  fs::remove_all(unpacked, ec);
  fs::remove_all(package, ec);
}

void make_private(const fs::path& path) {
  std::error_code ec;
  auto apply = [&](const fs::path& p) {
    const auto st = fs::symlink_status(p, ec);
    if (fs::is_directory(st)) fs::permissions(p, fs::perms::owner_all, ec);
    else if (fs::is_regular_file(st)) fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write, ec);
  };
  apply(path);
  if (fs::is_directory(fs::symlink_status(path, ec)))
    for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      apply(it->path());
}

Status transfer_tree(const fs::path& from, const fs::path& to, bool move) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  if (move) {
    fs::rename(from, to, ec);
    if (!ec) return {};
    if (ec != std::errc::cross_device_link)
      return fail(ErrorCode::kIo, "move " + from.string() + " -> " + to.string() + ": " + ec.message());
    ec.clear();
  }
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::copy_symlinks, ec);
  if (ec) return fail(ErrorCode::kIo, "copy " + from.string() + " -> " + to.string() + ": " + ec.message());
  if (move) fs::remove_all(from, ec);
  return {};
}

fs::path unique_child(const fs::path& dir, const std::string& base) {
  const fs::path b(base);
  const std::string ext = b.has_stem() && b.has_extension() ? b.extension().string() : "";
  const std::string stem = base.substr(0, base.size() - ext.size());
  fs::path p = dir / base;
  for (int i = 2; fs::exists(fs::symlink_status(p)); ++i) p = dir / (stem + "-" + std::to_string(i) + ext);
  return p;
}

}  // namespace tp::host
