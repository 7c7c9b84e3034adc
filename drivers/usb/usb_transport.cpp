// drivers/usb/usb_transport.cpp: finding, claiming, resetting and reconnecting the USB printer.
#include "drivers/usb/usb_transport.h"

#include <cstdio>
#include <thread>

#include "drivers/common/internal/log.h"
#include "drivers/usb/ieee1284_id.h"
#include "drivers/usb/internal/usb_impl.h"

namespace tp::drivers {

using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

namespace {

// USB printer class (USB Device Class Definition for Printing Devices 1.1).
constexpr std::uint8_t kPrinterClass = 7;
constexpr std::uint8_t kGetDeviceId = 0;
constexpr std::uint8_t kGetPortStatus = 1;
constexpr std::uint8_t kSoftReset = 2;
constexpr unsigned kControlTimeoutMs = 2000;
// bmRequestType of class requests to the interface (USB 2.0 9.3.1).
constexpr std::uint8_t kClassInterfaceIn = 0xA1;
constexpr std::uint8_t kClassInterfaceOut = 0x21;

std::shared_ptr<spdlog::logger> log() { return drivers_log(); }

struct Candidate {
  int iface = -1, alt = 0;
  std::uint8_t config_index = 0, ep_out = 0, ep_in = 0;
};

// The first interface setting of printer class with a bulk OUT and a bulk IN endpoint.
bool find_printer_interface(libusb_device* dev, Candidate& c) {
  libusb_config_descriptor* cfg = nullptr;
  if (libusb_get_active_config_descriptor(dev, &cfg) != 0 && libusb_get_config_descriptor(dev, 0, &cfg) != 0)
    return false;
  bool found = false;
  for (int i = 0; i < cfg->bNumInterfaces && !found; ++i) {
    const libusb_interface& itf = cfg->interface[i];
    for (int a = 0; a < itf.num_altsetting && !found; ++a) {
      const libusb_interface_descriptor& d = itf.altsetting[a];
      if (d.bInterfaceClass != kPrinterClass) continue;
      std::uint8_t out = 0, in = 0;
      for (int e = 0; e < d.bNumEndpoints; ++e) {
        const auto& ep = d.endpoint[e];
        if ((ep.bmAttributes & 3) != LIBUSB_TRANSFER_TYPE_BULK) continue;
        if (ep.bEndpointAddress & LIBUSB_ENDPOINT_IN) in = in ? in : ep.bEndpointAddress;
        else out = out ? out : ep.bEndpointAddress;
      }
      if (out && in) {
        c = Candidate{d.bInterfaceNumber, d.bAlternateSetting, 0, out, in};
        found = true;
      }
    }
  }
  libusb_free_config_descriptor(cfg);
  return found;
}

std::string read_device_id(libusb_device_handle* h, const Candidate& c) {
  unsigned char buf[1024];
  const int n = libusb_control_transfer(
      h, kClassInterfaceIn, kGetDeviceId, c.config_index,
      static_cast<std::uint16_t>((c.iface << 8) | c.alt), buf, sizeof buf - 1, kControlTimeoutMs);
  if (n < 2) return {};
  // Two-byte big-endian length (including itself), then the ID text.
  std::size_t len = static_cast<std::size_t>(buf[0] << 8 | buf[1]);
  if (len < 2 || len > static_cast<std::size_t>(n)) len = static_cast<std::size_t>(n);
  return std::string(reinterpret_cast<const char*>(buf + 2), len - 2);
}

}  // namespace

std::string usb_error_text(int code) {
  return std::string(libusb_error_name(code)) + " (" + libusb_strerror(static_cast<libusb_error>(code)) + ")";
}

Status UsbTransport::Impl::find_and_open() {
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &list);
  if (n < 0) return fail(ErrorCode::kIo, "listing USB devices: " + usb_error_text(static_cast<int>(n)));
  std::string seen;
  Error last{ErrorCode::kNotFound, ""};
  bool opened = false;
  for (ssize_t i = 0; i < n && !opened; ++i) {
    libusb_device* dev = list[i];
    libusb_device_descriptor dd{};
    if (libusb_get_device_descriptor(dev, &dd) != 0) continue;
    if (opt.match.vendor_id && dd.idVendor != *opt.match.vendor_id) continue;
    if (opt.match.product_id && dd.idProduct != *opt.match.product_id) continue;
    Candidate c;
    if (!find_printer_interface(dev, c)) continue;
    char where[64];
    std::snprintf(where, sizeof where, "usb %u:%u %04x:%04x", libusb_get_bus_number(dev),
                  libusb_get_device_address(dev), dd.idVendor, dd.idProduct);
    libusb_device_handle* h = nullptr;
    if (int r = libusb_open(dev, &h); r != 0) {
      last = Error{r == LIBUSB_ERROR_ACCESS ? ErrorCode::kAccess : ErrorCode::kIo,
                   std::string(where) + ": cannot open: " + usb_error_text(r)};
      seen += std::string(seen.empty() ? "" : ", ") + where + " (not openable)";
      continue;
    }
    // A real box has the kernel's usblp bound to the interface: let libusb detach it.
    libusb_set_auto_detach_kernel_driver(h, 1);
    const std::string id = read_device_id(h, c);
    seen += std::string(seen.empty() ? "" : ", ") + where + " '" + id + "'";
    if (!ieee1284_matches(id, opt.match.ieee1284)) {
      libusb_close(h);
      continue;
    }
    if (int r = libusb_claim_interface(h, c.iface); r != 0) {
      last = Error{r == LIBUSB_ERROR_BUSY ? ErrorCode::kBusy : ErrorCode::kIo,
                   std::string(where) + ": cannot claim interface " + std::to_string(c.iface) + ": " + usb_error_text(r)};
      libusb_close(h);
      continue;
    }
    if (c.alt != 0) libusb_set_interface_alt_setting(h, c.iface, c.alt);
    handle = h;
    iface = c.iface;
    alt = c.alt;
    config_index = c.config_index;
    ep_out = c.ep_out;
    ep_in = c.ep_in;
    dev_id = id;
    const auto fields = parse_ieee1284_id(id);
    auto mdl = fields.find("MDL");
    desc = std::string(where) + (mdl != fields.end() ? " '" + mdl->second + "'" : "");
    opened = true;
  }
  libusb_free_device_list(list, 1);
  if (opened) return {};
  if (!last.message.empty()) return fail(last);
  std::string want = "a USB printer-class device";
  char ids[32];
  if (opt.match.vendor_id || opt.match.product_id) {
    std::snprintf(ids, sizeof ids, " %04x:%04x", opt.match.vendor_id.value_or(0), opt.match.product_id.value_or(0));
    want += ids;
  }
  if (!opt.match.ieee1284.empty()) want += " whose device ID has '" + opt.match.ieee1284 + "'";
  return fail(ErrorCode::kNotFound, "no " + want + " found (printers seen: " + (seen.empty() ? "none" : seen) + ")");
}

void UsbTransport::Impl::start() {
  disconnected = out_stalled = in_stalled = closing = false;
  rx.clear();
  out.clear();
  in.clear();
  out.resize(static_cast<std::size_t>(std::max(1, opt.out_transfers)));
  in.resize(static_cast<std::size_t>(std::max(1, opt.in_transfers)));
  for (auto& s : out) {
    s.owner = this;
    s.xfer = libusb_alloc_transfer(0);
    s.buf.resize(opt.out_transfer_bytes);
  }
  for (auto& s : in) {
    s.owner = this;
    s.xfer = libusb_alloc_transfer(0);
    s.buf.resize(opt.in_transfer_bytes);
  }
  stop_events = false;
  events = std::thread([this] {
    // libusb's completions and callbacks all run on this thread.
    while (!stop_events.load()) {
      timeval tv{0, 100000};
      libusb_handle_events_timeout_completed(ctx, &tv, nullptr);
    }
  });
  for (auto& s : in) submit_in(s);
}

void UsbTransport::Impl::teardown() {
  if (!ctx) return;
  if (handle) {
    // Cancel what is in flight (outside our lock: completions take it) and let the event
    // thread collect the cancellations.
    std::vector<libusb_transfer*> live;
    {
      std::lock_guard guard(m);
      closing = true;
      for (auto& s : out)
        if (s.state == OutSlot::State::kInFlight) live.push_back(s.xfer);
      for (auto& s : in)
        if (s.busy) live.push_back(s.xfer);
    }
    for (libusb_transfer* t : live) libusb_cancel_transfer(t);
    std::unique_lock lock(m);
    const bool idle = cv.wait_for(lock, milliseconds(2000), [&] {
      for (auto& s : out)
        if (s.state == OutSlot::State::kInFlight) return false;
      for (auto& s : in)
        if (s.busy) return false;
      return true;
    });
    lock.unlock();
    stop_events = true;
    libusb_interrupt_event_handler(ctx);
    if (events.joinable()) events.join();
    if (idle) {
      for (auto& s : out) libusb_free_transfer(s.xfer);
      for (auto& s : in) libusb_free_transfer(s.xfer);
    } else {
      log()->warn("{}: transfers still in flight at close; leaking them rather than freeing live memory", desc);
    }
    out.clear();
    in.clear();
    libusb_release_interface(handle, iface);
    libusb_close(handle);
    handle = nullptr;
  }
  libusb_exit(ctx);
  ctx = nullptr;
}

UsbTransport::UsbTransport(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

UsbTransport::~UsbTransport() {
  if (impl_->handle) (void)impl_->drain(milliseconds(2000));
  impl_->teardown();
}

Result<std::unique_ptr<UsbTransport>> UsbTransport::open(const UsbOptions& options, milliseconds find_timeout) {
  auto impl = std::make_unique<Impl>();
  impl->opt = options;
  const auto deadline = Clock::now() + find_timeout;
  for (;;) {
    if (int r = libusb_init(&impl->ctx); r != 0)
      return fail(ErrorCode::kIo, "libusb_init: " + usb_error_text(r));
    auto s = impl->find_and_open();
    if (s) break;
    libusb_exit(impl->ctx);
    impl->ctx = nullptr;
    if (Clock::now() >= deadline) return fail(s.error());
    std::this_thread::sleep_for(milliseconds(50));
  }
  impl->start();
  log()->info("{}: claimed interface {} (OUT 0x{:02x}, IN 0x{:02x})", impl->desc, impl->iface, impl->ep_out,
              impl->ep_in);
  return std::unique_ptr<UsbTransport>(new UsbTransport(std::move(impl)));
}

device::Status UsbTransport::write(std::span<const std::uint8_t> bytes) { return impl_->write(bytes); }

device::Result<std::size_t> UsbTransport::read(std::span<std::uint8_t> buffer, milliseconds timeout) {
  return impl_->read(buffer, timeout);
}

device::Status UsbTransport::drain(milliseconds timeout) { return impl_->drain(timeout); }

device::Status UsbTransport::reset() {
  if (!impl_->handle) return device::fail(device::ErrorCode::kDisconnected, "usb: not connected");
  if (auto s = impl_->drain(milliseconds(3000)); !s) return s;
  const int r = libusb_control_transfer(impl_->handle, kClassInterfaceOut, kSoftReset, 0, static_cast<std::uint16_t>(impl_->iface << 8), nullptr, 0,
                                        kControlTimeoutMs);
  if (r == LIBUSB_ERROR_NO_DEVICE) return device::fail(device::ErrorCode::kDisconnected, impl_->desc + ": unplugged");
  if (r < 0) return device::fail(device::ErrorCode::kTransport, impl_->desc + ": SOFT_RESET: " + usb_error_text(r));
  std::lock_guard lock(impl_->m);
  impl_->rx.clear();
  ++impl_->stats.soft_resets;
  return {};
}

device::Status UsbTransport::reconnect(milliseconds timeout) {
  const std::string old = impl_->desc;
  impl_->teardown();
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    if (libusb_init(&impl_->ctx) == 0) {
      if (impl_->find_and_open()) break;
      libusb_exit(impl_->ctx);
      impl_->ctx = nullptr;
    }
    if (Clock::now() >= deadline)
      return device::fail(device::ErrorCode::kDisconnected,
                          old + ": printer did not come back within " + std::to_string(timeout.count()) + " ms");
    std::this_thread::sleep_for(milliseconds(50));
  }
  impl_->start();
  ++impl_->stats.reconnects;
  log()->info("{}: reconnected as {}", old, impl_->desc);
  return {};
}

std::string UsbTransport::describe() const { return impl_->desc; }

std::string UsbTransport::device_id() const { return impl_->dev_id; }

Result<std::uint8_t> UsbTransport::port_status() {
  unsigned char b = 0;
  const int r = libusb_control_transfer(impl_->handle, kClassInterfaceIn, kGetPortStatus, 0, static_cast<std::uint16_t>(impl_->iface), &b, 1,
                                        kControlTimeoutMs);
  if (r != 1) return fail(ErrorCode::kIo, impl_->desc + ": GET_PORT_STATUS: " + usb_error_text(r < 0 ? r : LIBUSB_ERROR_IO));
  return b;
}

UsbStats UsbTransport::stats() const {
  std::lock_guard lock(impl_->m);
  return impl_->stats;
}

}  // namespace tp::drivers
