// drivers/usb/usb_transfers.cpp: bulk streaming for UsbTransport: OUT transfers in flight with
// in-order resend after a stall or timeout, IN transfers always pending for status.
#include <algorithm>
#include <cstring>

#include "drivers/common/internal/log.h"
#include "drivers/usb/internal/usb_impl.h"

namespace tp::drivers {

using std::chrono::milliseconds;
using DevErr = device::ErrorCode;

namespace {

void out_callback(libusb_transfer* t) {
  auto* slot = static_cast<OutSlot*>(t->user_data);
  UsbTransport::Impl* impl = slot->owner;
  {
    std::lock_guard lock(impl->m);
    switch (t->status) {
      case LIBUSB_TRANSFER_COMPLETED:
        slot->state = OutSlot::State::kFree;
        slot->timeouts = 0;
        ++impl->stats.out_transfers;
        impl->stats.out_bytes += static_cast<std::uint64_t>(t->actual_length);
        break;
      case LIBUSB_TRANSFER_STALL:
        // The endpoint halted; what the printer took before stays taken.
        slot->offset += static_cast<std::size_t>(t->actual_length);
        slot->state = OutSlot::State::kFailed;
        impl->out_stalled = true;
        break;
      case LIBUSB_TRANSFER_TIMED_OUT:
        slot->offset += static_cast<std::size_t>(t->actual_length);
        slot->state = OutSlot::State::kFailed;
        ++slot->timeouts;
        ++impl->stats.timeouts;
        break;
      case LIBUSB_TRANSFER_CANCELLED:
        slot->state = OutSlot::State::kFree;
        break;
      default:  // NO_DEVICE, ERROR, OVERFLOW: the device is gone or unusable
        slot->state = OutSlot::State::kFree;
        impl->disconnected = true;
        break;
    }
  }
  impl->cv.notify_all();
}

void in_callback(libusb_transfer* t) {
  auto* slot = static_cast<InSlot*>(t->user_data);
  UsbTransport::Impl* impl = slot->owner;
  bool resubmit = false;
  {
    std::lock_guard lock(impl->m);
    slot->busy = false;
    switch (t->status) {
      case LIBUSB_TRANSFER_COMPLETED:
        impl->rx.insert(impl->rx.end(), t->buffer, t->buffer + t->actual_length);
        ++impl->stats.in_transfers;
        impl->stats.in_bytes += static_cast<std::uint64_t>(t->actual_length);
        resubmit = !impl->disconnected && !impl->closing;
        break;
      case LIBUSB_TRANSFER_TIMED_OUT:
        resubmit = !impl->disconnected && !impl->closing;
        break;
      case LIBUSB_TRANSFER_STALL: impl->in_stalled = true; break;
      case LIBUSB_TRANSFER_CANCELLED: break;
      default: impl->disconnected = true; break;
    }
  }
  if (resubmit) impl->submit_in(*slot);
  impl->cv.notify_all();
}

}  // namespace

void UsbTransport::Impl::submit_in(InSlot& slot) {
  libusb_fill_bulk_transfer(slot.xfer, handle, ep_in, slot.buf.data(), static_cast<int>(slot.buf.size()), in_callback,
                            &slot, 0);
  {
    std::lock_guard lock(m);
    if (closing) return;
    slot.busy = true;
  }
  if (int r = libusb_submit_transfer(slot.xfer); r != 0) {
    std::lock_guard lock(m);
    slot.busy = false;
    if (r == LIBUSB_ERROR_NO_DEVICE) disconnected = true;
    else if (r == LIBUSB_ERROR_PIPE) in_stalled = true;
  }
}

void UsbTransport::Impl::recover_in(std::unique_lock<std::mutex>& lock) {
  if (!in_stalled || disconnected) return;
  for (auto& s : in)
    if (s.busy) return;
  in_stalled = false;
  lock.unlock();
  if (libusb_clear_halt(handle, ep_in) == 0) {
    ++stats.stalls;
    for (auto& s : in) submit_in(s);
  }
  lock.lock();
}

device::Status UsbTransport::Impl::recover_out(std::unique_lock<std::mutex>& lock) {
  // Resend only once nothing is in flight, so the byte stream keeps its order.
  std::vector<OutSlot*> failed;
  for (auto& s : out) {
    if (s.state == OutSlot::State::kInFlight) return {};
    if (s.state == OutSlot::State::kFailed) failed.push_back(&s);
  }
  if (failed.empty()) return {};
  std::sort(failed.begin(), failed.end(), [](const OutSlot* a, const OutSlot* b) { return a->order < b->order; });
  for (OutSlot* s : failed)
    if (s->timeouts >= opt.max_timeouts)
      return device::fail(DevErr::kTimeout, desc + ": printer took nothing on bulk OUT for " +
                                                   std::to_string(s->timeouts) + " x " +
                                                   std::to_string(opt.write_timeout.count()) + " ms");
  const bool stalled = out_stalled;
  out_stalled = false;
  for (OutSlot* s : failed) s->state = OutSlot::State::kInFlight;
  lock.unlock();
  if (stalled) {
    if (int r = libusb_clear_halt(handle, ep_out); r != 0) {
      lock.lock();
      for (OutSlot* s : failed) s->state = OutSlot::State::kFailed;
      if (r == LIBUSB_ERROR_NO_DEVICE) disconnected = true;
      return device::fail(r == LIBUSB_ERROR_NO_DEVICE ? DevErr::kDisconnected : DevErr::kTransport,
                          desc + ": clearing the halt on bulk OUT: " + usb_error_text(r));
    }
    ++stats.stalls;
    drivers_log()->info("{}: bulk OUT stalled; halt cleared, resending {} transfers", desc, failed.size());
  }
  for (OutSlot* s : failed) {
    libusb_fill_bulk_transfer(s->xfer, handle, ep_out, s->buf.data() + s->offset,
                              static_cast<int>(s->len - s->offset), out_callback, s,
                              static_cast<unsigned>(opt.write_timeout.count()));
    if (int r = libusb_submit_transfer(s->xfer); r != 0) {
      lock.lock();
      s->state = OutSlot::State::kFailed;
      if (r == LIBUSB_ERROR_NO_DEVICE) disconnected = true;
      else if (r == LIBUSB_ERROR_PIPE) out_stalled = true;
      return {};
    }
  }
  lock.lock();
  return {};
}

device::Status UsbTransport::Impl::write(std::span<const std::uint8_t> bytes) {
  std::size_t pos = 0;
  while (pos < bytes.size()) {
    std::unique_lock lock(m);
    OutSlot* slot = nullptr;
    const auto deadline = std::chrono::steady_clock::now() + opt.write_timeout * (opt.max_timeouts + 1);
    while (!slot) {
      if (disconnected) return device::fail(DevErr::kDisconnected, desc + ": unplugged");
      if (auto s = recover_out(lock); !s) return s;
      bool any_failed = false;
      for (auto& s : out) any_failed |= s.state == OutSlot::State::kFailed;
      if (!any_failed)
        for (auto& s : out)
          if (s.state == OutSlot::State::kFree) {
            slot = &s;
            break;
          }
      if (slot) break;
      if (cv.wait_until(lock, deadline) == std::cv_status::timeout)
        return device::fail(DevErr::kTimeout, desc + ": no bulk OUT transfer completed in time");
    }
    const std::size_t n = std::min(bytes.size() - pos, opt.out_transfer_bytes);
    std::memcpy(slot->buf.data(), bytes.data() + pos, n);
    slot->len = n;
    slot->offset = 0;
    slot->timeouts = 0;
    slot->order = next_order++;
    slot->state = OutSlot::State::kInFlight;
    lock.unlock();
    libusb_fill_bulk_transfer(slot->xfer, handle, ep_out, slot->buf.data(), static_cast<int>(n), out_callback, slot,
                              static_cast<unsigned>(opt.write_timeout.count()));
    if (int r = libusb_submit_transfer(slot->xfer); r != 0) {
      lock.lock();
      if (r == LIBUSB_ERROR_NO_DEVICE) {
        slot->state = OutSlot::State::kFree;
        disconnected = true;
        return device::fail(DevErr::kDisconnected, desc + ": unplugged");
      }
      if (r == LIBUSB_ERROR_PIPE) {
        // Halted before we got here: resend this one with the others after clearing it.
        slot->state = OutSlot::State::kFailed;
        out_stalled = true;
      } else {
        slot->state = OutSlot::State::kFree;
        return device::fail(DevErr::kTransport, desc + ": submitting bulk OUT: " + usb_error_text(r));
      }
    }
    pos += n;
  }
  return {};
}

device::Status UsbTransport::Impl::drain(milliseconds timeout) {
  std::unique_lock lock(m);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (disconnected) return device::fail(DevErr::kDisconnected, desc + ": unplugged");
    if (auto s = recover_out(lock); !s) return s;
    bool busy = false;
    for (auto& s : out) busy |= s.state != OutSlot::State::kFree;
    if (!busy) return {};
    if (cv.wait_until(lock, deadline) == std::cv_status::timeout)
      return device::fail(DevErr::kTimeout, desc + ": bulk OUT not drained within " +
                                                   std::to_string(timeout.count()) + " ms");
  }
}

device::Result<std::size_t> UsbTransport::Impl::read(std::span<std::uint8_t> buffer, milliseconds timeout) {
  std::unique_lock lock(m);
  recover_in(lock);
  // Waiting for status is also when stalled OUT transfers get resent.
  if (auto s = recover_out(lock); !s) return device::fail(s.error());
  if (rx.empty() && !disconnected && timeout.count() > 0)
    cv.wait_for(lock, timeout, [&] { return !rx.empty() || disconnected || in_stalled || out_stalled; });
  if (!rx.empty()) {
    const std::size_t n = std::min(buffer.size(), rx.size());
    std::copy_n(rx.begin(), n, buffer.begin());
    rx.erase(rx.begin(), rx.begin() + static_cast<long>(n));
    return n;
  }
  if (disconnected) return device::fail(DevErr::kDisconnected, desc + ": unplugged");
  recover_in(lock);
  return std::size_t{0};
}

}  // namespace tp::drivers
