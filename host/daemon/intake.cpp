// host/daemon/intake.cpp: package checks and spool moves shared by the hot folder and the socket.
#include "host/daemon/intake.h"

#include <unistd.h>

#include "host/job/manifest.h"
#include "host/job/package.h"

namespace tp::host {

namespace fs = std::filesystem;

Result<CheckedPackage> check_package(const fs::path& path, const fs::path& scratch_dir) {
  fs::path unpack = scratch_dir / ("check-" + std::to_string(::getpid()) + "-" + path.filename().string());
  std::error_code ec;
  fs::remove_all(unpack, ec);
  Result<CheckedPackage> out = CheckedPackage{};
  if (auto pkg = JobPackage::open(path, unpack); !pkg) {
    out = std::unexpected(pkg.error());
  } else if (auto job = load_job(*pkg); !job) {
    out = std::unexpected(job.error());
  } else {
    out = CheckedPackage{job->name, path};
  }
  fs::remove_all(unpack, ec);
  return out;
}

Result<Job> open_spooled_job(const fs::path& package) {
  fs::path unpack = package;
  unpack += ".unpacked";
  std::error_code ec;
  if (!fs::is_directory(package)) fs::remove_all(unpack, ec);
  auto pkg = JobPackage::open(package, unpack);
  if (!pkg) return std::unexpected(pkg.error());
  return load_job(*pkg);
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
  fs::path p = dir / base;
  for (int i = 2; fs::exists(fs::symlink_status(p)); ++i) p = dir / (base + "-" + std::to_string(i));
  return p;
}

}  // namespace tp::host
