// host/common/sha256.h: SHA-256 (libmd's, FIPS 180-4) for job content hashes (idempotent submit)
// and the plan's input digests.
#pragma once

#include <array>
#include <memory>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "host/common/error.h"

namespace tp::host {

/// Incremental SHA-256. Copyable, so a digest can be taken of a prefix and hashing go on.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256& other);
  Sha256& operator=(const Sha256& other);
  void update(std::string_view bytes);
  /// The digest as 64 lower-case hex digits of the bytes so far; the object is unchanged.
  std::string hex_digest() const;

 private:
  struct Context;  // libmd's SHA2_CTX, kept out of this header
  std::unique_ptr<Context> ctx_;
};

/// Hash of a job package: a file's bytes, or a folder's sorted relative paths, file types and
/// contents (symlinks by their target text), so the same package hashes the same wherever it is.
/// Fails (kIo) naming the file that cannot be read.
[[nodiscard]] Result<std::string> package_hash(const std::filesystem::path& package);

}  // namespace tp::host
