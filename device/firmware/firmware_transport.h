// device/firmware/firmware_transport.h: a Transport whose other end is a PrinterController in the
// same process: the host's protocol code talks to the real firmware without USB. For unit tests
// and tools; it can also play an unplugged cable.
#pragma once

#include <chrono>
#include <functional>
#include <mutex>

#include "device/firmware/controller.h"
#include "device/protocol/transport.h"

namespace tp::device {

class FirmwareTransport final : public Transport {
 public:
  /// `controller` must outlive the transport.
  explicit FirmwareTransport(PrinterController& controller);

  [[nodiscard]] Status write(std::span<const std::uint8_t> bytes) override;
  [[nodiscard]] Result<std::size_t> read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
  [[nodiscard]] Status reset() override;
  [[nodiscard]] Status reconnect(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

  /// Plays an unplugged (false) or replugged (true) cable: while unplugged every call fails
  /// with kDisconnected; replugging resets the printer's link as a new USB connection would.
  void set_connected(bool connected);
  /// Runs `fn` on the controller under the transport's lock (from another thread, e.g. a test
  /// clearing a pause while the host streams).
  void with_controller(const std::function<void(PrinterController&)>& fn);
  /// Microseconds since the transport was made: the controller's clock.
  [[nodiscard]] std::int64_t now_us() const;

 private:
  PrinterController& controller_;
  std::chrono::steady_clock::time_point start_;
  // Recursive: a controller observer may unplug the cable from inside write().
  mutable std::recursive_mutex mutex_;
  bool connected_ = true;
  bool needs_reconnect_ = false;
};

}  // namespace tp::device
