// host/common/sha256.h: SHA-256 (FIPS 180-4) for job content hashes (idempotent submit).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "host/common/error.h"

namespace tp::host {

/// Incremental SHA-256.
class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  /// The digest as 64 lower-case hex digits; the object is spent afterwards.
  std::string hex_digest();

 private:
  void block(const std::uint8_t* p);
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buf_{};
  size_t used_ = 0;
  std::uint64_t total_bytes_ = 0;
};

/// Hash of a job package: a file's bytes, or a folder's sorted relative paths, file types and
/// contents (symlinks by their target text), so the same package hashes the same wherever it is.
/// Fails (kIo) naming the file that cannot be read.
[[nodiscard]] Result<std::string> package_hash(const std::filesystem::path& package);

}  // namespace tp::host
