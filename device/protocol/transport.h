// device/protocol/transport.h: the byte pipe between host and printer. USB (drivers/), the
// in-process firmware (device/firmware) and the recording wrapper implement it; the protocol
// code above never knows which one it talks to.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>

#include "device/common/error.h"

namespace tp::device {

class Transport {
 public:
  virtual ~Transport() = default;

  /// Queues `bytes` for the printer, in order. Blocks while the transport's queue is full.
  /// Fails with kDisconnected when the device is gone (call reconnect()), kTimeout if the
  /// printer accepted nothing for the transport's write timeout, kTransport otherwise.
  [[nodiscard]] virtual Status write(std::span<const std::uint8_t> bytes) = 0;

  /// Copies up to `buffer.size()` bytes received from the printer, waiting up to `timeout` for
  /// the first; returns 0 if none came. Fails like write().
  [[nodiscard]] virtual Result<std::size_t> read(std::span<std::uint8_t> buffer,
                                                 std::chrono::milliseconds timeout) = 0;

  /// Drops what is queued in both directions and resets the printer's receiver (USB printer
  /// class SOFT_RESET), so the next byte written starts a fresh frame.
  [[nodiscard]] virtual Status reset() = 0;

  /// After kDisconnected: waits up to `timeout` for the printer to come back and reopens it.
  [[nodiscard]] virtual Status reconnect(std::chrono::milliseconds timeout) = 0;

  /// For logs: which device this is ("usb 1-3 1d6b:0104 'TP-SIM-1600'").
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace tp::device
