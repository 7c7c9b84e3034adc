// drivers/usb/usb_transport.h: the printer link over USB with libusb: finds a printer-class
// device (by vendor/product or by its IEEE 1284 device ID), claims it, streams with several
// asynchronous bulk OUT transfers in flight, reads status on bulk IN, and survives a stall
// (clear halt and resend), a timeout and an unplug (reconnect() re-finds the device).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "device/protocol/transport.h"
#include "drivers/common/error.h"

namespace tp::drivers {

/// Which printer to use. With neither ids nor pattern, the first printer-class device wins.
struct UsbMatch {
  std::optional<std::uint16_t> vendor_id;
  std::optional<std::uint16_t> product_id;
  /// Fields the IEEE 1284 device ID must carry ("CMD:TPWP;" = speaks this project's protocol,
  /// "MDL:TP-SIM-1600;" = that model); see ieee1284_matches().
  std::string ieee1284 = "CMD:TPWP;";
};

struct UsbOptions {
  UsbMatch match;
  std::size_t out_transfer_bytes = 256u << 10;  ///< bytes per bulk OUT transfer
  int out_transfers = 4;                        ///< bulk OUT transfers in flight
  std::size_t in_transfer_bytes = 16u << 10;
  int in_transfers = 2;
  /// A bulk OUT transfer the printer does not take within this time times out and is resent;
  /// `max_timeouts` in a row fail the write with kTimeout.
  std::chrono::milliseconds write_timeout{5000};
  int max_timeouts = 3;
};

struct UsbStats {
  std::uint64_t out_transfers = 0;
  std::uint64_t out_bytes = 0;
  std::uint64_t in_transfers = 0;
  std::uint64_t in_bytes = 0;
  std::uint64_t stalls = 0;      ///< halts cleared (OUT and IN)
  std::uint64_t timeouts = 0;
  std::uint64_t reconnects = 0;
  std::uint64_t soft_resets = 0;
};

class UsbTransport final : public device::Transport {
 public:
  /// Finds and claims the printer, retrying until `find_timeout`. Fails with kNotFound (names
  /// what was looked for and what printer-class devices were seen), kAccess, kBusy or kIo.
  [[nodiscard]] static Result<std::unique_ptr<UsbTransport>> open(
      const UsbOptions& options, std::chrono::milliseconds find_timeout = std::chrono::milliseconds(0));
  ~UsbTransport() override;
  UsbTransport(const UsbTransport&) = delete;
  UsbTransport& operator=(const UsbTransport&) = delete;

  [[nodiscard]] device::Status write(std::span<const std::uint8_t> bytes) override;
  [[nodiscard]] device::Result<std::size_t> read(std::span<std::uint8_t> buffer,
                                                 std::chrono::milliseconds timeout) override;
  [[nodiscard]] device::Status reset() override;
  [[nodiscard]] device::Status reconnect(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

  /// Waits until every bulk OUT transfer has completed (resending after stalls).
  [[nodiscard]] device::Status drain(std::chrono::milliseconds timeout);
  /// The printer's IEEE 1284 device ID as read at open.
  [[nodiscard]] std::string device_id() const;
  /// USB GET_PORT_STATUS: bit 0x08 not error, 0x10 selected, 0x20 paper empty.
  [[nodiscard]] Result<std::uint8_t> port_status();
  [[nodiscard]] UsbStats stats() const;

  struct Impl;

 private:
  explicit UsbTransport(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::drivers
