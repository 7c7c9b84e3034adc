// device/swath/packbits.cpp: PackBits encoder and bounds-checked decoder.
#include "device/swath/packbits.h"

#include <string>

namespace tp::device {

void packbits_encode(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out) {
  const std::size_t n = raw.size();
  std::size_t i = 0;
  while (i < n) {
    // A repeat packet pays off from three equal bytes on.
    std::size_t run = 1;
    while (i + run < n && run < 128 && raw[i + run] == raw[i]) ++run;
    if (run >= 3) {
      out.push_back(static_cast<std::uint8_t>(static_cast<std::int8_t>(1 - static_cast<int>(run))));
      out.push_back(raw[i]);
      i += run;
      continue;
    }
    // Literal packet: extend until a run of three starts or 128 bytes are collected.
    std::size_t start = i;
    std::size_t len = 0;
    while (i < n && len < 128) {
      if (i + 2 < n && raw[i] == raw[i + 1] && raw[i] == raw[i + 2]) break;
      ++i;
      ++len;
    }
    out.push_back(static_cast<std::uint8_t>(len - 1));
    out.insert(out.end(), raw.begin() + static_cast<long>(start), raw.begin() + static_cast<long>(start + len));
  }
}

Status packbits_decode(std::span<const std::uint8_t> packed, std::size_t expected_bytes,
                       std::vector<std::uint8_t>& out) {
  const std::size_t base = out.size();
  out.reserve(base + expected_bytes);
  std::size_t i = 0;
  auto too_long = [&](std::size_t at) {
    return fail(ErrorCode::kInvalidArgument, "packbits: decodes past the expected " +
                                                 std::to_string(expected_bytes) + " bytes at input offset " +
                                                 std::to_string(at));
  };
  while (i < packed.size()) {
    const auto h = static_cast<std::int8_t>(packed[i]);
    const std::size_t at = i++;
    if (h >= 0) {
      const std::size_t len = static_cast<std::size_t>(h) + 1;
      if (packed.size() - i < len)
        return fail(ErrorCode::kInvalidArgument,
                    "packbits: literal packet at input offset " + std::to_string(at) + " runs past the end");
      if (out.size() - base + len > expected_bytes) return too_long(at);
      out.insert(out.end(), packed.begin() + static_cast<long>(i), packed.begin() + static_cast<long>(i + len));
      i += len;
    } else if (h != -128) {
      const std::size_t len = static_cast<std::size_t>(1 - h);
      if (i >= packed.size())
        return fail(ErrorCode::kInvalidArgument,
                    "packbits: repeat packet at input offset " + std::to_string(at) + " lacks its byte");
      if (out.size() - base + len > expected_bytes) return too_long(at);
      out.insert(out.end(), len, packed[i++]);
    }
  }
  if (out.size() - base != expected_bytes)
    return fail(ErrorCode::kInvalidArgument, "packbits: decoded " + std::to_string(out.size() - base) +
                                                 " bytes, expected " + std::to_string(expected_bytes));
  return {};
}

}  // namespace tp::device
