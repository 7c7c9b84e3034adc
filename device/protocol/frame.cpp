// device/protocol/frame.cpp: frame encoding and the resynchronising frame decoder.
#include "device/protocol/frame.h"

#include <cstring>
#include <string>

#include "device/protocol/crc.h"
#include "device/protocol/internal/byte_io.h"

namespace tp::device {

std::string_view to_string(MessageType type) {
  switch (type) {
#define TP_MESSAGE_NAME(name, code, wire, Payload) \
  case MessageType::name: return #wire;
    TP_PROTOCOL_MESSAGES(TP_MESSAGE_NAME)
#undef TP_MESSAGE_NAME
  }
  return "unknown";
}

bool is_message_type(std::uint8_t value) {
  return to_string(static_cast<MessageType>(value)) != "unknown";
}

Status encode_frame(MessageType type, std::uint32_t seq, std::span<const std::uint8_t> payload,
                    std::vector<std::uint8_t>& out, std::uint16_t flags) {
  if (payload.size() > kMaxFramePayloadBytes)
    return fail(ErrorCode::kInvalidArgument,
                std::string(to_string(type)) + " frame: payload of " + std::to_string(payload.size()) +
                    " bytes exceeds the " + std::to_string(kMaxFramePayloadBytes) + "-byte limit");
  const std::size_t start = out.size();
  out.reserve(start + kFrameOverheadBytes + payload.size());
  wire::ByteWriter w(out);
  w.u16(kFrameMagic);
  w.u8(kFrameVersion);
  w.u8(static_cast<std::uint8_t>(type));
  w.u32(seq);
  w.u32(static_cast<std::uint32_t>(payload.size()));
  w.u16(flags);
  w.u16(crc16_ccitt(std::span(out.data() + start, 14)));
  w.bytes(payload);
  w.u32(crc32(payload));
  return {};
}

FrameDecoder::FrameDecoder(std::uint32_t max_payload_bytes) : max_payload_bytes_(max_payload_bytes) {}

void FrameDecoder::feed(std::span<const std::uint8_t> bytes) {
  // Compact before growing so the buffer stays about one frame long on a steady stream.
  if (pos_ > 0 && (pos_ == buf_.size() || pos_ > (1u << 16))) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<long>(pos_));
    pos_ = 0;
  }
  buf_.insert(buf_.end(), bytes.begin(), bytes.end());
}

void FrameDecoder::reset() {
  buf_.clear();
  pos_ = 0;
  resyncing_ = false;
}

namespace {
std::uint16_t le16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }
std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
}  // namespace

bool FrameDecoder::header_valid(const std::uint8_t* p) const {
  if (le16(p) != kFrameMagic || p[2] != kFrameVersion || !is_message_type(p[3])) return false;
  if (le32(p + 8) > max_payload_bytes_) return false;
  return crc16_ccitt(std::span(p, 14)) == le16(p + 14);
}

std::optional<Result<Frame>> FrameDecoder::next() {
  while (buf_.size() - pos_ >= kFrameHeaderBytes) {
    const std::uint8_t* p = buf_.data() + pos_;
    if (!header_valid(p)) {
      // Scan forward one byte at a time; report the loss of sync once per episode.
      ++pos_;
      ++bytes_skipped_;
      if (!resyncing_) {
        resyncing_ = true;
        ++header_errors_;
        return Result<Frame>(std::unexpected(
            Error{ErrorCode::kMalformedFrame, "frame header invalid (magic, version, type, length or CRC); resynchronising"}));
      }
      continue;
    }
    resyncing_ = false;
    const std::uint32_t len = le32(p + 8);
    const std::size_t total = kFrameOverheadBytes + len;
    if (buf_.size() - pos_ < total) return std::nullopt;
    Frame f;
    f.header.type = static_cast<MessageType>(p[3]);
    f.header.seq = le32(p + 4);
    f.header.payload_bytes = len;
    f.header.flags = le16(p + 12);
    if (tamper_) tamper_(f.header, std::span(buf_.data() + pos_ + kFrameHeaderBytes, len + kFrameTrailerBytes));
    std::span<const std::uint8_t> payload(p + kFrameHeaderBytes, len);
    const std::uint32_t want = le32(p + kFrameHeaderBytes + len);
    pos_ += total;
    if (crc32(payload) != want) {
      ++crc_errors_;
      return Result<Frame>(std::unexpected(Error{
          ErrorCode::kCrcMismatch, "frame seq " + std::to_string(f.header.seq) + " (" +
                                       std::string(to_string(f.header.type)) + ", " + std::to_string(len) +
                                       " bytes): payload CRC mismatch"}));
    }
    f.payload.assign(payload.begin(), payload.end());
    return Result<Frame>(std::move(f));
  }
  return std::nullopt;
}

}  // namespace tp::device
