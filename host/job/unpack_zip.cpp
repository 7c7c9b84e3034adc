// host/job/unpack_zip.cpp: safe zip extraction: path checks, no links, size and ratio limits
// enforced on the bytes actually inflated (headers are not trusted).
#include <zip.h>
#include <sys/stat.h>

#include <fstream>
#include <memory>
#include <vector>

#include "host/job/package.h"

namespace tp::host {

namespace fs = std::filesystem;

namespace {
struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};
}  // namespace

Status unpack_zip(const fs::path& zip_path, const fs::path& dest, const PackageLimits& limits) {
  const std::string ctx = zip_path.string();
  int err = 0;
  std::unique_ptr<zip_t, ZipCloser> z(zip_open(zip_path.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &err));
  if (!z) {
    zip_error_t ze;
    zip_error_init_with_code(&ze, err);
    std::string msg = zip_error_strerror(&ze);
    zip_error_fini(&ze);
    return fail(ErrorCode::kArchive, ctx + ": not a readable zip archive (" + msg + ")");
  }
  zip_int64_t n = zip_get_num_entries(z.get(), 0);
  if (n < 0 || static_cast<std::uint64_t>(n) > limits.max_entries)
    return fail(ErrorCode::kArchive, ctx + ": " + std::to_string(n) + " entries (limit " +
                                         std::to_string(limits.max_entries) + ")");

  std::uint64_t total_out = 0, total_in = 0;
  std::vector<char> buf(1 << 16);
  for (zip_int64_t i = 0; i < n; ++i) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(z.get(), static_cast<zip_uint64_t>(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
      return fail(ErrorCode::kArchive, ctx + ": entry " + std::to_string(i) + " is unreadable");
    const std::string name = st.name;
    const std::string ectx = ctx + ": entry \"" + name + "\"";

    // Symlinks (and devices) recorded in Unix attributes are refused outright.
    zip_uint8_t opsys = 0;
    zip_uint32_t attr = 0;
    if (zip_file_get_external_attributes(z.get(), static_cast<zip_uint64_t>(i), 0, &opsys, &attr) == 0 &&
        opsys == ZIP_OPSYS_UNIX) {
      mode_t mode = static_cast<mode_t>(attr >> 16);
      // Writers such as Python's zipfile.writestr store permission bits without a file type
      // (0600): such an entry is a plain file (or a folder, by its trailing '/').
      if ((mode & S_IFMT) != 0) {
        if (S_ISLNK(mode)) return fail(ErrorCode::kUnsafePath, ectx + " is a symbolic link");
        if (!S_ISREG(mode) && !S_ISDIR(mode))
          return fail(ErrorCode::kUnsafePath, ectx + " is not a regular file or folder");
      }
    }
    std::string rel = name;
    bool is_dir = !rel.empty() && rel.back() == '/';
    if (is_dir) rel.pop_back();
    if (rel.empty()) continue;
    if (auto ok = check_relative_path(rel); !ok) return std::unexpected(ok.error().with_context(ectx));

    fs::path out_path = dest / rel;
    std::error_code ec;
    if (is_dir) {
      fs::create_directories(out_path, ec);
      if (ec) return fail(ErrorCode::kIo, ectx + ": " + ec.message());
      continue;
    }
    fs::create_directories(out_path.parent_path(), ec);
    if (ec) return fail(ErrorCode::kIo, ectx + ": " + ec.message());
    if (fs::exists(fs::symlink_status(out_path)))
      return fail(ErrorCode::kArchive, ectx + " appears twice in the archive");

    std::unique_ptr<zip_file_t, ZipFileCloser> f(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(i), 0));
    if (!f) return fail(ErrorCode::kArchive, ectx + ": cannot open (" + zip_strerror(z.get()) + ")");
    std::ofstream out(out_path, std::ios::binary | std::ios::trunc);
    if (!out) return fail(ErrorCode::kIo, ectx + ": cannot write " + out_path.string());

    // Count what is really inflated; stop the moment a limit is crossed.
    const std::uint64_t compressed = (st.valid & ZIP_STAT_COMP_SIZE) ? st.comp_size : 0;
    total_in += compressed;
    std::uint64_t entry_out = 0;
    for (;;) {
      zip_int64_t got = zip_fread(f.get(), buf.data(), buf.size());
      if (got < 0) return fail(ErrorCode::kArchive, ectx + ": corrupt data (" + zip_file_strerror(f.get()) + ")");
      if (got == 0) break;
      entry_out += static_cast<std::uint64_t>(got);
      total_out += static_cast<std::uint64_t>(got);
      if (entry_out > limits.max_entry_bytes)
        return fail(ErrorCode::kArchive, ectx + " inflates past the per-file limit of " +
                                             std::to_string(limits.max_entry_bytes) +
                                             " bytes (max_zip_entry_bytes; raise it with --limit max_zip_entry_bytes=N)");
      if (total_out > limits.max_total_bytes)
        return fail(ErrorCode::kArchive, ctx + ": archive inflates past the limit of " +
                                             std::to_string(limits.max_total_bytes) +
                                             " bytes (max_zip_bytes; raise it with --limit max_zip_bytes=N)");
      // Ratio checks only bite past 1 MiB, so small highly compressible files stay fine.
      if (entry_out > (1u << 20) && entry_out > limits.max_ratio * static_cast<double>(compressed + 1))
        return fail(ErrorCode::kArchive, ectx + " has a compression ratio over " +
                                             std::to_string(static_cast<int>(limits.max_ratio)) +
                                             ":1 (decompression bomb?)");
      out.write(buf.data(), got);
      if (!out) return fail(ErrorCode::kIo, ectx + ": write failed");
    }
  }
  if (total_out > (1u << 20) && total_out > limits.max_ratio * static_cast<double>(total_in + 1))
    return fail(ErrorCode::kArchive, ctx + ": overall compression ratio over " +
                                         std::to_string(static_cast<int>(limits.max_ratio)) + ":1");
  return {};
}

}  // namespace tp::host
