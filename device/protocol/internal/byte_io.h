// device/protocol/internal/byte_io.h: little-endian writers and bounds-checked readers for
// message payloads (private to device/protocol).
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tp::device::wire {

/// Appends little-endian fields to a byte vector.
class ByteWriter {
 public:
  explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void u8(std::uint8_t v) { out_.push_back(v); }
  void u16(std::uint16_t v) { put(v, 2); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void i32(std::int32_t v) { put(static_cast<std::uint32_t>(v), 4); }
  void i64(std::int64_t v) { put(static_cast<std::uint64_t>(v), 8); }
  /// A string as u16 length + bytes; longer strings are cut at 65535 bytes.
  void str(std::string_view s) {
    std::size_t n = s.size() > 0xFFFF ? 0xFFFF : s.size();
    u16(static_cast<std::uint16_t>(n));
    out_.insert(out_.end(), s.begin(), s.begin() + static_cast<long>(n));
  }
  void bytes(std::span<const std::uint8_t> b) { out_.insert(out_.end(), b.begin(), b.end()); }

 private:
  void put(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::vector<std::uint8_t>& out_;
};

/// Reads little-endian fields; the first read past the end marks the reader failed and names
/// the field, later reads return zeros so decoders can check once at the end.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> in) : in_(in) {}
  std::uint8_t u8(const char* field) { return static_cast<std::uint8_t>(get(1, field)); }
  std::uint16_t u16(const char* field) { return static_cast<std::uint16_t>(get(2, field)); }
  std::uint32_t u32(const char* field) { return static_cast<std::uint32_t>(get(4, field)); }
  std::uint64_t u64(const char* field) { return get(8, field); }
  std::int32_t i32(const char* field) { return static_cast<std::int32_t>(static_cast<std::uint32_t>(get(4, field))); }
  std::int64_t i64(const char* field) { return static_cast<std::int64_t>(get(8, field)); }
  std::string str(const char* field) {
    std::size_t n = u16(field);
    if (!need(n, field)) return {};
    std::string s(reinterpret_cast<const char*>(in_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  /// The next `n` bytes as a view (empty and failed if fewer remain).
  std::span<const std::uint8_t> bytes(std::size_t n, const char* field) {
    if (!need(n, field)) return {};
    auto s = in_.subspan(pos_, n);
    pos_ += n;
    return s;
  }
  std::span<const std::uint8_t> rest() {
    auto s = in_.subspan(pos_);
    pos_ = in_.size();
    return s;
  }
  [[nodiscard]] bool ok() const { return failed_field_ == nullptr; }
  [[nodiscard]] const char* failed_field() const { return failed_field_; }
  [[nodiscard]] std::size_t remaining() const { return in_.size() - pos_; }

 private:
  bool need(std::size_t n, const char* field) {
    if (failed_field_) return false;
    if (in_.size() - pos_ < n) {
      failed_field_ = field;
      pos_ = in_.size();
      return false;
    }
    return true;
  }
  std::uint64_t get(int n, const char* field) {
    if (!need(static_cast<std::size_t>(n), field)) return 0;
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t(in_[pos_ + static_cast<std::size_t>(i)]) << (8 * i);
    pos_ += static_cast<std::size_t>(n);
    return v;
  }
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
  const char* failed_field_ = nullptr;
};

}  // namespace tp::device::wire
