// host/pipeline/input_hash.cpp: the digest of a pipeline step's inputs (see internal/input_hash.h).
#include "host/pipeline/internal/input_hash.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

namespace tp::host::internal {

void InputHash::mix(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t a = a_, b = b_;
  for (std::size_t i = 0; i < size; ++i) {
    a = (a ^ p[i]) * 0x100000001b3ull;  // FNV-1a
    b = (b + p[i] + 1) * 0xff51afd7ed558ccdull;
    b ^= b >> 29;
  }
  a_ = a, b_ = b;
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

std::string InputHash::hex() const {
  char buf[33];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(a_),
                static_cast<unsigned long long>(b_));
  return buf;
}

}  // namespace tp::host::internal
