// device/protocol/crc.h: checksums of the wire protocol: CRC-16/CCITT for frame headers and
// CRC-32 (IEEE 802.3) for payloads and whole swaths.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace tp::device {

/// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection) of `bytes`.
/// Check value: crc16_ccitt("123456789") == 0x29B1.
std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes);

/// CRC-32 (IEEE 802.3, reflected poly 0xEDB88320, init and final xor 0xFFFFFFFF).
/// Check value: crc32("123456789") == 0xCBF43926.
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

/// Continues a CRC-32 over more bytes: crc32_update(crc32(a), b) == crc32(a ++ b).
/// Start a running CRC with `crc = 0`.
std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> bytes);

}  // namespace tp::device
