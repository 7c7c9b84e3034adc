// host/pipeline/internal/input_hash.h: a digest (SHA-256, first 128 bits) of what a pipeline step reads (job fields,
// file bytes, upstream results), to tell whether a stored plan step is still valid.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "host/common/error.h"
#include "host/common/sha256.h"

namespace tp::host::internal {

/// Accumulates labelled values into a digest. Every value is framed with its label and length,
/// so ("ab", "c") and ("a", "bc") differ. Doubles are hashed by their bit pattern.
class InputHash {
 public:
  InputHash& add(std::string_view label, std::string_view bytes);
  InputHash& add(std::string_view label, const char* text) { return add(label, std::string_view(text)); }
  InputHash& add(std::string_view label, const std::string& text) { return add(label, std::string_view(text)); }
  InputHash& add(std::string_view label, double value);
  InputHash& add(std::string_view label, std::int64_t value);
  InputHash& add(std::string_view label, int value) { return add(label, static_cast<std::int64_t>(value)); }
  InputHash& add(std::string_view label, bool value) { return add(label, static_cast<std::int64_t>(value)); }
  /// The file's bytes (read in blocks). Fails (kIo) naming the file when it cannot be read.
  [[nodiscard]] Status add_file(std::string_view label, const std::filesystem::path& path);
  /// 32 lower-case hex digits.
  [[nodiscard]] std::string hex() const;

 private:
  void mix(const void* data, std::size_t size);
  Sha256 sha_;
};

}  // namespace tp::host::internal
