// host/pipeline/input_hash.cpp: the digest of a pipeline step's inputs (see internal/input_hash.h).
#include "host/pipeline/internal/input_hash.h"

#include <cstring>
#include <fstream>
#include <vector>

namespace tp::host::internal {

void InputHash::mix(const void* data, std::size_t size) {
  sha_.update(std::string_view(static_cast<const char*>(data), size));
}

InputHash& InputHash::add(std::string_view label, std::string_view bytes) {
  const std::uint64_t ln = label.size(), n = bytes.size();
  mix(&ln, sizeof ln);
  mix(label.data(), label.size());
  mix(&n, sizeof n);
  mix(bytes.data(), bytes.size());
  return *this;
}

InputHash& InputHash::add(std::string_view label, double value) {
  if (value == 0) value = 0;  // -0 and +0 are the same input
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  return add(label, std::string_view(raw, sizeof raw));
}

InputHash& InputHash::add(std::string_view label, std::int64_t value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  return add(label, std::string_view(raw, sizeof raw));
}

Status InputHash::add_file(std::string_view label, const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path.string() + ": cannot read (plan inputs)");
  const std::uint64_t ln = label.size();
  mix(&ln, sizeof ln);
  mix(label.data(), label.size());
  std::vector<char> buf(1 << 16);
  std::uint64_t total = 0;
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    mix(buf.data(), got);
    total += got;
  }
  if (in.bad()) return fail(ErrorCode::kIo, path.string() + ": read error (plan inputs)");
  mix(&total, sizeof total);
  return {};
}

std::string InputHash::hex() const { return sha_.hex_digest().substr(0, 32); }

}  // namespace tp::host::internal
