// device/firmware/link_receiver.h: the printer's end of the link: turns the OUT byte stream into
// intact, in-sequence frames, counts what was lost and keeps the NAK state the status reports.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "device/protocol/frame.h"

namespace tp::device {

/// What fault injection does to one frame on the wire.
enum class RxFault : std::uint8_t { kNone, kDrop, kCorrupt };

/// Consulted for every frame with a valid header, numbered from 1 since the receiver was made.
using RxFaultHook = std::function<RxFault(std::uint64_t frame_number, const FrameHeader& header)>;

/// Go-back-N receiver: accepts frame `ack_seq()` and nothing else; on the first loss (payload
/// CRC mismatch or a sequence gap) it counts one NAK and drops frames until the host resends
/// from ack_seq(). A hello (sequence 0) always passes and restarts the sequence at 1.
class LinkReceiver {
 public:
  LinkReceiver();

  void feed(std::span<const std::uint8_t> bytes) { decoder_.feed(bytes); }
  /// The next frame to act on, or nullopt when more bytes are needed.
  std::optional<Frame> next();
  /// Forgets partial input and expects sequence 1 (USB soft reset, reconnect).
  void reset();
  void set_fault_hook(RxFaultHook hook) { hook_ = std::move(hook); }

  [[nodiscard]] std::uint32_t ack_seq() const { return expected_; }
  [[nodiscard]] std::uint32_t naks() const { return naks_; }
  [[nodiscard]] std::uint32_t crc_errors() const { return crc_errors_; }
  [[nodiscard]] std::uint32_t gaps() const { return gaps_; }
  [[nodiscard]] std::uint32_t duplicates() const { return duplicates_; }
  [[nodiscard]] std::uint64_t frames_on_wire() const { return frame_number_; }
  [[nodiscard]] std::uint32_t injected_drops() const { return injected_drops_; }
  [[nodiscard]] std::uint32_t injected_corruptions() const { return injected_corruptions_; }

 private:
  void nak();

  FrameDecoder decoder_;
  RxFaultHook hook_;
  std::uint64_t frame_number_ = 0;
  bool drop_current_ = false;
  std::uint32_t expected_ = 1;
  bool in_nak_ = false;
  std::uint32_t naks_ = 0;
  std::uint32_t crc_errors_ = 0;
  std::uint32_t gaps_ = 0;
  std::uint32_t duplicates_ = 0;
  std::uint32_t injected_drops_ = 0;
  std::uint32_t injected_corruptions_ = 0;
};

}  // namespace tp::device
