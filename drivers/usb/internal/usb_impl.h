// drivers/usb/internal/usb_impl.h: UsbTransport's state (private: it holds libusb types).
#pragma once

#include <libusb.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "drivers/usb/usb_transport.h"

namespace tp::drivers {

struct OutSlot {
  enum class State { kFree, kInFlight, kFailed };
  UsbTransport::Impl* owner = nullptr;
  libusb_transfer* xfer = nullptr;
  std::vector<std::uint8_t> buf;
  std::size_t len = 0;     ///< bytes of buf to send
  std::size_t offset = 0;  ///< bytes already taken by the printer (after a stall or timeout)
  State state = State::kFree;
  std::uint64_t order = 0;  ///< submission order: resends keep the byte stream in order
  int timeouts = 0;
};

struct InSlot {
  UsbTransport::Impl* owner = nullptr;
  libusb_transfer* xfer = nullptr;
  std::vector<std::uint8_t> buf;
  bool busy = false;
};

struct UsbTransport::Impl {
  UsbOptions opt;
  libusb_context* ctx = nullptr;
  libusb_device_handle* handle = nullptr;
  int iface = -1;
  int alt = 0;
  std::uint8_t config_index = 0;
  std::uint8_t ep_out = 0;
  std::uint8_t ep_in = 0;
  std::string desc;
  std::string dev_id;

  std::thread events;
  std::atomic<bool> stop_events{false};

  mutable std::mutex m;
  std::condition_variable cv;
  std::vector<OutSlot> out;
  std::vector<InSlot> in;
  std::deque<std::uint8_t> rx;
  bool disconnected = false;
  bool closing = false;  ///< teardown: completions must not resubmit
  bool out_stalled = false;
  bool in_stalled = false;
  std::uint64_t next_order = 0;
  UsbStats stats;

  // usb_transport.cpp: finding, opening and closing.
  [[nodiscard]] Status find_and_open();
  void start();
  void teardown();
  // usb_transfers.cpp: bulk streaming.
  [[nodiscard]] device::Status write(std::span<const std::uint8_t> bytes);
  [[nodiscard]] device::Result<std::size_t> read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout);
  [[nodiscard]] device::Status drain(std::chrono::milliseconds timeout);
  [[nodiscard]] device::Status recover_out(std::unique_lock<std::mutex>& lock);
  void recover_in(std::unique_lock<std::mutex>& lock);
  void submit_in(InSlot& slot);
};

/// "LIBUSB_ERROR_NO_DEVICE (No such device ...)" for messages.
std::string usb_error_text(int code);

}  // namespace tp::drivers
