// device/firmware/link_receiver.cpp: sequence checking, NAK state and fault injection on receive.
#include "device/firmware/link_receiver.h"

namespace tp::device {

LinkReceiver::LinkReceiver() {
  decoder_.set_tamper([this](const FrameHeader& h, std::span<std::uint8_t> payload) {
    ++frame_number_;
    drop_current_ = false;
    if (!hook_) return;
    switch (hook_(frame_number_, h)) {
      case RxFault::kNone: break;
      case RxFault::kDrop:
        drop_current_ = true;
        ++injected_drops_;
        break;
      case RxFault::kCorrupt:
        // Flip one bit, as line noise would (in the CRC trailer if the payload is empty).
        payload[(payload.size() - 4) / 2] ^= 0x10;
        ++injected_corruptions_;
        break;
    }
  });
}

void LinkReceiver::nak() {
  if (in_nak_) return;
  in_nak_ = true;
  ++naks_;
}

void LinkReceiver::reset() {
  decoder_.reset();
  expected_ = 1;
  in_nak_ = false;
}

std::optional<Frame> LinkReceiver::next() {
  while (auto r = decoder_.next()) {
    if (!*r) {
      if (r->error().code == ErrorCode::kCrcMismatch) {
        ++crc_errors_;
        nak();
      }
      continue;
    }
    if (drop_current_) {
      drop_current_ = false;
      continue;
    }
    Frame f = std::move(**r);
    if (f.header.type == MessageType::kHello) {
      expected_ = 1;
      in_nak_ = false;
      return f;
    }
    if (f.header.seq == expected_) {
      ++expected_;
      in_nak_ = false;
      return f;
    }
    if (f.header.seq < expected_) {
      ++duplicates_;
    } else {
      ++gaps_;
      nak();
    }
  }
  return std::nullopt;
}

}  // namespace tp::device
