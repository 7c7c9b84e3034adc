// device/firmware/firmware_transport.cpp: the in-process transport to a PrinterController.
#include "device/firmware/firmware_transport.h"

#include <algorithm>
#include <cstring>
#include <thread>

namespace tp::device {

using std::chrono::milliseconds;

FirmwareTransport::FirmwareTransport(PrinterController& controller)
    : controller_(controller), start_(std::chrono::steady_clock::now()) {}

std::int64_t FirmwareTransport::now_us() const {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start_).count();
}

Status FirmwareTransport::write(std::span<const std::uint8_t> bytes) {
  std::lock_guard lock(mutex_);
  if (!connected_ || needs_reconnect_) return fail(ErrorCode::kDisconnected, describe() + ": unplugged");
  controller_.receive(bytes, now_us());
  return {};
}

Result<std::size_t> FirmwareTransport::read(std::span<std::uint8_t> buffer, milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (!connected_ || needs_reconnect_) return fail(ErrorCode::kDisconnected, describe() + ": unplugged");
      controller_.advance(now_us());
      auto out = controller_.transmit(buffer.size());
      if (!out.empty()) {
        std::memcpy(buffer.data(), out.data(), out.size());
        return out.size();
      }
    }
    if (std::chrono::steady_clock::now() >= deadline) return std::size_t{0};
    std::this_thread::sleep_for(milliseconds(1));
  }
}

Status FirmwareTransport::reset() {
  std::lock_guard lock(mutex_);
  if (!connected_ || needs_reconnect_) return fail(ErrorCode::kDisconnected, describe() + ": unplugged");
  controller_.link_reset();
  return {};
}

Status FirmwareTransport::reconnect(milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (connected_) {
        needs_reconnect_ = false;
        controller_.link_reset();
        return {};
      }
    }
    if (std::chrono::steady_clock::now() >= deadline)
      return fail(ErrorCode::kDisconnected, describe() + ": printer did not come back within " +
                                                std::to_string(timeout.count()) + " ms");
    std::this_thread::sleep_for(milliseconds(5));
  }
}

void FirmwareTransport::set_connected(bool connected) {
  std::lock_guard lock(mutex_);
  if (!connected) needs_reconnect_ = true;
  connected_ = connected;
}

void FirmwareTransport::with_controller(const std::function<void(PrinterController&)>& fn) {
  std::lock_guard lock(mutex_);
  fn(controller_);
}

std::string FirmwareTransport::describe() const { return "in-process printer '" + controller_.model().name + "'"; }

}  // namespace tp::device
