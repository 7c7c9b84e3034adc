// device/protocol/frame.h: the framing of the wire protocol: message types, frame encoding and a
// streaming frame decoder that resynchronises after corruption.
//
// Frame layout (little-endian):
//   0  u16 magic 0x5054 ("TP")   2 u8 frame version (1)   3 u8 message type
//   4  u32 sequence number       8 u32 payload length     12 u16 flags
//   14 u16 CRC-16/CCITT of bytes 0..13
//   16 payload                   16+N u32 CRC-32 of the payload
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "device/common/error.h"
#include "device/protocol/message_table.h"

namespace tp::device {

/// Every message of the protocol (message_table.h). Values below 0x80 travel host -> printer,
/// above printer -> host.
enum class MessageType : std::uint8_t {
#define TP_MESSAGE_ENUMERATOR(name, code, wire, Payload) name = code,
  TP_PROTOCOL_MESSAGES(TP_MESSAGE_ENUMERATOR)
#undef TP_MESSAGE_ENUMERATOR
};

/// Every MessageType, in table order.
inline constexpr MessageType kAllMessageTypes[] = {
#define TP_MESSAGE_LIST(name, code, wire, Payload) MessageType::name,
    TP_PROTOCOL_MESSAGES(TP_MESSAGE_LIST)
#undef TP_MESSAGE_LIST
};

/// Short stable name ("swath_data"), "unknown" for values outside the enum.
std::string_view to_string(MessageType type);
/// True if `value` is one of MessageType's values.
bool is_message_type(std::uint8_t value);

inline constexpr std::uint16_t kFrameMagic = 0x5054;  // bytes 'T' 'P'
inline constexpr std::uint8_t kFrameVersion = 1;
inline constexpr std::size_t kFrameHeaderBytes = 16;
inline constexpr std::size_t kFrameTrailerBytes = 4;
inline constexpr std::size_t kFrameOverheadBytes = kFrameHeaderBytes + kFrameTrailerBytes;
/// Largest payload either side accepts; a header announcing more is treated as corrupt.
inline constexpr std::uint32_t kMaxFramePayloadBytes = 1u << 20;

/// Frame flag bits.
inline constexpr std::uint16_t kFrameFlagRetransmit = 0x0001;  ///< informative: a resent frame

struct FrameHeader {
  MessageType type = MessageType::kStatusQuery;
  std::uint32_t seq = 0;
  std::uint32_t payload_bytes = 0;
  std::uint16_t flags = 0;
};

struct Frame {
  FrameHeader header;
  std::vector<std::uint8_t> payload;
};

/// Appends the frame for (`type`, `seq`, `payload`) to `out`. Payloads over
/// kMaxFramePayloadBytes are a programming error and fail with kInvalidArgument.
[[nodiscard]] Status encode_frame(MessageType type, std::uint32_t seq, std::span<const std::uint8_t> payload,
                                  std::vector<std::uint8_t>& out, std::uint16_t flags = 0);

/// Splits a byte stream into frames. Feed bytes as they arrive; take frames and errors with
/// next(). A header with a bad magic, version, length or CRC makes the decoder scan forward
/// byte by byte for the next valid header; a payload CRC mismatch skips that one frame and is
/// reported as kCrcMismatch naming the frame's sequence number and type.
class FrameDecoder {
 public:
  explicit FrameDecoder(std::uint32_t max_payload_bytes = kMaxFramePayloadBytes);

  /// Appends received bytes.
  void feed(std::span<const std::uint8_t> bytes);
  /// The next complete frame or decoding error; nullopt when more bytes are needed.
  std::optional<Result<Frame>> next();
  /// Drops buffered bytes (after a link reset).
  void reset();

  /// Fault injection (the simulator's "corrupt a CRC"): called with each frame whose header is
  /// valid, before its payload CRC is checked; it may alter the payload and its CRC trailer
  /// (`bytes` holds both: payload_bytes + 4 bytes).
  using Tamper = std::function<void(const FrameHeader&, std::span<std::uint8_t> bytes)>;
  void set_tamper(Tamper tamper) { tamper_ = std::move(tamper); }

  [[nodiscard]] std::size_t buffered_bytes() const { return buf_.size() - pos_; }
  [[nodiscard]] std::uint64_t bytes_skipped() const { return bytes_skipped_; }
  [[nodiscard]] std::uint64_t crc_errors() const { return crc_errors_; }
  [[nodiscard]] std::uint64_t header_errors() const { return header_errors_; }

 private:
  bool header_valid(const std::uint8_t* p) const;

  std::uint32_t max_payload_bytes_;
  std::vector<std::uint8_t> buf_;
  std::size_t pos_ = 0;
  bool resyncing_ = false;
  std::uint64_t bytes_skipped_ = 0;
  std::uint64_t crc_errors_ = 0;
  std::uint64_t header_errors_ = 0;
  Tamper tamper_;
};

}  // namespace tp::device
