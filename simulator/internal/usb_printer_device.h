// simulator/internal/usb_printer_device.h: an emulated USB printer-class device in a umockdev
// testbed: sysfs entry and descriptors, and a usbfs ioctl handler (URB submit, reap, discard;
// control requests including the printer class GET_DEVICE_ID, GET_PORT_STATUS, SOFT_RESET)
// that feeds bulk OUT to the printer controller and answers bulk IN from it.
#pragma once

#include <umockdev.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "device/firmware/controller.h"
#include "simulator/common/error.h"

namespace tp::sim {

struct UsbCounters {
  std::uint64_t out_urbs = 0;
  std::uint64_t out_bytes = 0;
  std::uint64_t in_urbs = 0;
  std::uint64_t in_bytes = 0;
  std::uint64_t control_requests = 0;
  std::uint64_t stalls = 0;       ///< times the bulk OUT endpoint halted
  std::uint64_t stalled_urbs = 0; ///< bulk OUT URBs failed because it was halted
  std::uint64_t halts_cleared = 0;
  std::uint64_t soft_resets = 0;
};

class UsbPrinterDevice {
 public:
  /// `controller` outlives the device. `reap_hold_ms`: how long an empty REAPURBNDELAY is held
  /// before answering EAGAIN (umockdev device nodes are plain files that always poll ready, so
  /// libusb would otherwise spin asking).
  /// umockdev answers ioctls on its own thread: `lock` guards everything the handler touches
  /// (this device, the controller, the recorder) against printsim's main loop.
  UsbPrinterDevice(UMockdevTestbed* testbed, device::PrinterController& controller, std::recursive_mutex& lock,
                   int busnum, int devnum, std::function<std::int64_t()> now_us, UsbCounters& counters,
                   unsigned reap_hold_ms = 2);
  ~UsbPrinterDevice();
  UsbPrinterDevice(const UsbPrinterDevice&) = delete;
  UsbPrinterDevice& operator=(const UsbPrinterDevice&) = delete;

  /// Adds the device to the testbed and starts answering its ioctls.
  [[nodiscard]] Status plug();
  /// Plays a pulled cable: pending URBs complete with -ESHUTDOWN, every later call fails with
  /// ENODEV, the device leaves sysfs. The client's open fd stays valid (its ioctls just fail).
  void unplug();
  /// The next bulk OUT URB stalls the endpoint; it stays halted until CLEAR_HALT.
  void inject_stall() { stall_next_out_ = true; }
  /// Hands queued controller output to pending IN URBs and completed URBs to held reaps.
  void service();
  [[nodiscard]] const std::string& devnode() const { return devnode_; }
  [[nodiscard]] bool plugged() const { return plugged_; }

 private:
  struct Urb {
    UMockdevIoctlData* data = nullptr;    // the client's usbdevfs_urb (owned ref)
    UMockdevIoctlData* buffer = nullptr;  // its data buffer (owned ref, may be null)
    unsigned long client_addr = 0;
    std::uint8_t type = 0;
    std::uint8_t endpoint = 0;
    int length = 0;
    int status = 0;
    int actual = 0;
  };
  struct ClientState {
    std::deque<Urb*> pending_in;
    std::deque<Urb*> completed;
    UMockdevIoctlClient* held_reap = nullptr;
    guint hold_timer = 0;
  };

  static gboolean on_ioctl(UMockdevIoctlBase* handler, UMockdevIoctlClient* client, gpointer self);
  static void on_vanished(UMockdevIoctlBase* handler, UMockdevIoctlClient* client, gpointer self);
  static gboolean on_hold_timeout(gpointer data);
  bool handle(UMockdevIoctlClient* client);
  void submit(UMockdevIoctlClient* client, ClientState& cs);
  void reap(UMockdevIoctlClient* client, ClientState& cs);
  void discard(UMockdevIoctlClient* client, ClientState& cs);
  void control(Urb& u);
  void bulk_out(Urb& u);
  void deliver(UMockdevIoctlClient* client, ClientState& cs);
  void release(Urb* u);
  std::string description() const;

  UMockdevTestbed* testbed_;
  device::PrinterController& controller_;
  std::recursive_mutex& lock_;
  int busnum_;
  int devnum_;
  std::function<std::int64_t()> now_us_;
  UsbCounters& counters_;
  unsigned reap_hold_ms_;
  std::string devnode_;
  std::string syspath_;
  UMockdevIoctlBase* handler_ = nullptr;
  std::map<UMockdevIoctlClient*, ClientState> clients_;
  bool plugged_ = false;
  bool unplugged_ = false;
  bool out_halted_ = false;
  bool in_halted_ = false;
  bool stall_next_out_ = false;
};

}  // namespace tp::sim
