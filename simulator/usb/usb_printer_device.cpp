// simulator/usb/usb_printer_device.cpp: the usbfs side of the emulated printer: URBs in and out
// of the printer controller, control requests, stalls and unplugging.
#include "simulator/internal/usb_printer_device.h"

#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "device/protocol/status_codes.h"
#include "simulator/internal/sim_log.h"
#include "simulator/usb/usb_descriptors.h"

namespace tp::sim {

namespace {

constexpr unsigned kCapabilities = USBDEVFS_CAP_BULK_SCATTER_GATHER | USBDEVFS_CAP_BULK_CONTINUATION |
                                   USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                                   USBDEVFS_CAP_REAP_AFTER_DISCONNECT | USBDEVFS_CAP_ZERO_PACKET;
constexpr std::size_t kSetupBytes = 8;

struct HoldTimer {
  UsbPrinterDevice* self;
  UMockdevIoctlClient* client;
};

UMockdevIoctlData* resolve(UMockdevIoctlData* parent, std::size_t offset, std::size_t len) {
  GError* err = nullptr;
  UMockdevIoctlData* d = umockdev_ioctl_data_resolve(parent, offset, len, &err);
  if (err) {
    sim_log()->warn("usb: resolving ioctl data: {}", err->message);
    g_error_free(err);
    return nullptr;
  }
  return d;
}

}  // namespace

UsbPrinterDevice::UsbPrinterDevice(UMockdevTestbed* testbed, device::PrinterController& controller,
                                   std::recursive_mutex& lock, int busnum, int devnum,
                                   std::function<std::int64_t()> now_us, UsbCounters& counters, unsigned reap_hold_ms)
    : testbed_(testbed),
      controller_(controller),
      lock_(lock),
      busnum_(busnum),
      devnum_(devnum),
      now_us_(std::move(now_us)),
      counters_(counters),
      reap_hold_ms_(reap_hold_ms) {
  char node[64];
  std::snprintf(node, sizeof node, "/dev/bus/usb/%03d/%03d", busnum, devnum);
  devnode_ = node;
  syspath_ = "/devices/pci0000:00/0000:00:14.0/usb" + std::to_string(busnum) + "/" + std::to_string(busnum) + "-1";
}

UsbPrinterDevice::~UsbPrinterDevice() {
  for (auto& [client, cs] : clients_) {
    if (cs.hold_timer) g_source_remove(cs.hold_timer);
    for (Urb* u : cs.pending_in) release(u);
    for (Urb* u : cs.completed) release(u);
  }
  if (handler_) g_object_unref(handler_);
}

std::string UsbPrinterDevice::description() const { return "usb " + devnode_; }

Status UsbPrinterDevice::plug() {
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(on_ioctl), this);
  g_signal_connect(handler_, "client-vanished", G_CALLBACK(on_vanished), this);
  GError* err = nullptr;
  // Attach the handler before the node appears, so the host can open it at once.
  if (!umockdev_testbed_attach_ioctl(testbed_, devnode_.c_str(), handler_, &err)) {
    std::string msg = err ? err->message : "unknown error";
    if (err) g_error_free(err);
    return fail(ErrorCode::kTestbed, description() + ": attaching the ioctl handler: " + msg);
  }
  const auto text = umockdev_usb_description(usb_identity(controller_.model()), busnum_, devnum_, syspath_);
  if (!umockdev_testbed_add_from_string(testbed_, text.c_str(), &err)) {
    std::string msg = err ? err->message : "unknown error";
    if (err) g_error_free(err);
    return fail(ErrorCode::kTestbed, description() + ": adding the device: " + msg);
  }
  plugged_ = true;
  sim_log()->info("{}: plugged in ({} at {})", description(), controller_.model().name, syspath_);
  return {};
}

void UsbPrinterDevice::unplug() {
  if (!plugged_ || unplugged_) return;
  unplugged_ = true;
  plugged_ = false;
  // The host controller gives back every URB in flight, as on a real disconnect.
  for (auto& [client, cs] : clients_) {
    for (Urb* u : cs.pending_in) {
      u->status = -ESHUTDOWN;
      u->actual = 0;
      cs.completed.push_back(u);
    }
    cs.pending_in.clear();
  }
  service();
  // umockdev names devices by their /sys path. No uevent: umockdev builds them with libudev in
  // the sending process, and printsim itself does not run under the preload. Hosts notice the
  // unplug from their failed URBs and re-enumerate.
  const std::string sys = "/sys" + syspath_;
  umockdev_testbed_remove_device(testbed_, sys.c_str());
  controller_.link_reset();
  sim_log()->info("{}: unplugged", description());
}

void UsbPrinterDevice::release(Urb* u) {
  if (u->buffer) g_object_unref(u->buffer);
  if (u->data) g_object_unref(u->data);
  delete u;
}

gboolean UsbPrinterDevice::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  auto* dev = static_cast<UsbPrinterDevice*>(self);
  std::lock_guard guard(dev->lock_);
  return dev->handle(client) ? TRUE : FALSE;
}

void UsbPrinterDevice::on_vanished(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  auto* dev = static_cast<UsbPrinterDevice*>(self);
  std::lock_guard guard(dev->lock_);
  auto it = dev->clients_.find(client);
  if (it == dev->clients_.end()) return;
  if (it->second.hold_timer) g_source_remove(it->second.hold_timer);
  if (it->second.held_reap) g_object_unref(it->second.held_reap);
  for (Urb* u : it->second.pending_in) dev->release(u);
  for (Urb* u : it->second.completed) dev->release(u);
  dev->clients_.erase(it);
}

bool UsbPrinterDevice::handle(UMockdevIoctlClient* client) {
  const unsigned long request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  ClientState& cs = clients_[client];
  if (unplugged_) {
    // After a disconnect the kernel still hands back given-back URBs, then says ENODEV.
    if ((request == USBDEVFS_REAPURBNDELAY || request == USBDEVFS_REAPURB) && !cs.completed.empty()) deliver(client, cs);
    else umockdev_ioctl_client_complete(client, -1, ENODEV);
    return true;
  }
  switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
      UMockdevIoctlData* d = resolve(arg, 0, sizeof(std::uint32_t));
      if (!d) return false;
      *reinterpret_cast<std::uint32_t*>(d->data) = kCapabilities;
      g_object_unref(d);
      umockdev_ioctl_client_complete(client, 0, 0);
      return true;
    }
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_SETINTERFACE:
    case USBDEVFS_SETCONFIGURATION:
    case USBDEVFS_RESETEP:
    case USBDEVFS_DISCONNECT_CLAIM:
      umockdev_ioctl_client_complete(client, 0, 0);
      return true;
    case USBDEVFS_CLEAR_HALT: {
      UMockdevIoctlData* d = resolve(arg, 0, sizeof(unsigned int));
      if (!d) return false;
      const unsigned ep = *reinterpret_cast<unsigned int*>(d->data);
      g_object_unref(d);
      if (ep == kBulkOutEndpoint) out_halted_ = false;
      if (ep == kBulkInEndpoint) in_halted_ = false;
      ++counters_.halts_cleared;
      umockdev_ioctl_client_complete(client, 0, 0);
      return true;
    }
    case USBDEVFS_RESET:
      out_halted_ = in_halted_ = false;
      controller_.link_reset();
      umockdev_ioctl_client_complete(client, 0, 0);
      return true;
    case USBDEVFS_GETDRIVER:
    case USBDEVFS_IOCTL:
      // No kernel driver is bound to the emulated interface.
      umockdev_ioctl_client_complete(client, -1, ENODATA);
      return true;
    case USBDEVFS_GET_SPEED:
      umockdev_ioctl_client_complete(client, 3 /* USB_SPEED_HIGH */, 0);
      return true;
    case USBDEVFS_SUBMITURB: submit(client, cs); return true;
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY: reap(client, cs); return true;
    case USBDEVFS_DISCARDURB: discard(client, cs); return true;
    default:
      umockdev_ioctl_client_complete(client, -1, ENOTTY);
      return true;
  }
}

void UsbPrinterDevice::submit(UMockdevIoctlClient* client, ClientState& cs) {
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  auto* u = new Urb;
  u->data = resolve(arg, 0, sizeof(usbdevfs_urb));
  if (!u->data) {
    delete u;
    umockdev_ioctl_client_complete(client, -1, EFAULT);
    return;
  }
  u->client_addr = u->data->client_addr;
  auto* urb = reinterpret_cast<usbdevfs_urb*>(u->data->data);
  u->type = urb->type;
  u->endpoint = urb->endpoint;
  u->length = urb->buffer_length;
  if (u->length > 0) u->buffer = resolve(u->data, offsetof(usbdevfs_urb, buffer), static_cast<std::size_t>(u->length));
  if (u->length > 0 && !u->buffer) {
    release(u);
    umockdev_ioctl_client_complete(client, -1, EFAULT);
    return;
  }
  if (u->type == USBDEVFS_URB_TYPE_CONTROL) {
    control(*u);
    cs.completed.push_back(u);
  } else if (u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == kBulkOutEndpoint) {
    bulk_out(*u);
    cs.completed.push_back(u);
  } else if (u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == kBulkInEndpoint) {
    if (in_halted_) {
      u->status = -EPIPE;
      cs.completed.push_back(u);
    } else {
      cs.pending_in.push_back(u);
    }
  } else {
    release(u);
    umockdev_ioctl_client_complete(client, -1, EINVAL);
    return;
  }
  umockdev_ioctl_client_complete(client, 0, 0);
  service();
}

void UsbPrinterDevice::bulk_out(Urb& u) {
  if (out_halted_ || stall_next_out_) {
    // A halted endpoint takes nothing until the host clears it.
    if (stall_next_out_) {
      sim_log()->info("{}: bulk OUT stalled (fault injection)", description());
      ++counters_.stalls;
    }
    stall_next_out_ = false;
    out_halted_ = true;
    u.status = -EPIPE;
    u.actual = 0;
    ++counters_.stalled_urbs;
    return;
  }
  controller_.receive(std::span(u.buffer->data, static_cast<std::size_t>(u.length)), now_us_());
  u.actual = u.length;
  ++counters_.out_urbs;
  counters_.out_bytes += static_cast<std::uint64_t>(u.length);
}

void UsbPrinterDevice::control(Urb& u) {
  ++counters_.control_requests;
  u.status = -EPIPE;  // stall unless answered below
  u.actual = 0;
  if (u.length < static_cast<int>(kSetupBytes)) return;
  std::uint8_t* b = u.buffer->data;
  const std::uint8_t type = b[0], req = b[1];
  const std::uint16_t value = static_cast<std::uint16_t>(b[2] | b[3] << 8);
  const std::uint16_t length = static_cast<std::uint16_t>(b[6] | b[7] << 8);
  const std::size_t room = std::min<std::size_t>(length, static_cast<std::size_t>(u.length) - kSetupBytes);
  const UsbIdentity id = usb_identity(controller_.model());
  auto reply = [&](const std::vector<std::uint8_t>& data) {
    const std::size_t n = std::min(room, data.size());
    std::memcpy(b + kSetupBytes, data.data(), n);
    u.actual = static_cast<int>(n);
    u.status = 0;
  };
  if (type == 0x80 && req == 6) {  // GET_DESCRIPTOR
    const std::uint8_t kind = value >> 8, index = value & 0xFF;
    if (kind == 1) reply(device_descriptor(id));
    else if (kind == 2 && index == 0) reply(config_descriptor());
    else if (kind == 3) {
      if (auto s = string_descriptor(id, index)) reply(*s);
    }
  } else if (type == 0x80 && req == 0) {  // GET_STATUS: self-powered
    reply({1, 0});
  } else if (type == 0x00 && (req == 9 || req == 1 || req == 3)) {  // SET_CONFIGURATION, features
    u.status = 0;
  } else if (type == 0xA1 && req == 0) {  // printer class GET_DEVICE_ID
    reply(device_id_reply(id));
  } else if (type == 0xA1 && req == 1) {  // GET_PORT_STATUS
    const auto st = controller_.status();
    std::uint8_t port = 0x18;  // selected, no error
    if (st.condition == device::PrinterCondition::kMediaOut) port |= 0x20;
    if (device::is_fault(st.condition)) port &= static_cast<std::uint8_t>(~0x08);
    reply({port});
  } else if ((type == 0x21 || type == 0x23) && req == 2) {  // SOFT_RESET
    controller_.link_reset();
    ++counters_.soft_resets;
    u.status = 0;
  }
}

void UsbPrinterDevice::reap(UMockdevIoctlClient* client, ClientState& cs) {
  if (!cs.completed.empty()) return deliver(client, cs);
  if (reap_hold_ms_ == 0 || cs.held_reap) {
    umockdev_ioctl_client_complete(client, -1, EAGAIN);
    return;
  }
  // Hold the empty reap briefly: a URB finishing meanwhile answers it at once. Nothing else
  // keeps the client object alive while its request is unanswered, so hold a reference.
  cs.held_reap = static_cast<UMockdevIoctlClient*>(g_object_ref(client));
  cs.hold_timer = g_timeout_add_full(G_PRIORITY_DEFAULT, reap_hold_ms_, on_hold_timeout, new HoldTimer{this, client},
                                     [](gpointer p) { delete static_cast<HoldTimer*>(p); });
}

gboolean UsbPrinterDevice::on_hold_timeout(gpointer data) {
  auto* t = static_cast<HoldTimer*>(data);
  std::lock_guard guard(t->self->lock_);
  auto it = t->self->clients_.find(t->client);
  if (it != t->self->clients_.end() && it->second.held_reap) {
    it->second.held_reap = nullptr;
    it->second.hold_timer = 0;
    umockdev_ioctl_client_complete(t->client, -1, EAGAIN);
    g_object_unref(t->client);
  }
  return G_SOURCE_REMOVE;
}

void UsbPrinterDevice::deliver(UMockdevIoctlClient* client, ClientState& cs) {
  Urb* u = cs.completed.front();
  cs.completed.pop_front();
  auto* urb = reinterpret_cast<usbdevfs_urb*>(u->data->data);
  urb->status = u->status;
  urb->actual_length = u->actual;
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  UMockdevIoctlData* slot = resolve(arg, 0, sizeof(void*));
  if (slot) {
    umockdev_ioctl_data_set_ptr(slot, 0, u->data);
    g_object_unref(slot);
  }
  umockdev_ioctl_client_complete(client, 0, 0);
  release(u);
}

void UsbPrinterDevice::discard(UMockdevIoctlClient* client, ClientState& cs) {
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const unsigned long addr = *reinterpret_cast<unsigned long*>(arg->data);
  auto it = std::find_if(cs.pending_in.begin(), cs.pending_in.end(), [&](Urb* u) { return u->client_addr == addr; });
  if (it == cs.pending_in.end()) {
    umockdev_ioctl_client_complete(client, -1, EINVAL);  // already completed
    return;
  }
  Urb* u = *it;
  cs.pending_in.erase(it);
  u->status = -ENOENT;
  u->actual = 0;
  cs.completed.push_back(u);
  umockdev_ioctl_client_complete(client, 0, 0);
}

void UsbPrinterDevice::service() {
  for (auto& [client, cs] : clients_) {
    // Controller output goes to the oldest IN URB, whole frames at a time.
    while (!cs.pending_in.empty() && !in_halted_ && controller_.has_output()) {
      Urb* u = cs.pending_in.front();
      auto bytes = controller_.transmit(static_cast<std::size_t>(u->length));
      if (bytes.empty()) break;
      std::memcpy(u->buffer->data, bytes.data(), bytes.size());
      u->actual = static_cast<int>(bytes.size());
      u->status = 0;
      cs.pending_in.pop_front();
      cs.completed.push_back(u);
      ++counters_.in_urbs;
      counters_.in_bytes += bytes.size();
    }
    if (cs.held_reap && !cs.completed.empty()) {
      UMockdevIoctlClient* c = cs.held_reap;
      cs.held_reap = nullptr;
      if (cs.hold_timer) g_source_remove(cs.hold_timer);
      cs.hold_timer = 0;
      deliver(c, cs);
      g_object_unref(c);
    }
  }
}

}  // namespace tp::sim
