// simulator/gpio/gpio_chip.cpp: the emulated GPIO chip of the cutting table.
#include "simulator/internal/gpio_chip.h"

#include <linux/gpio.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "simulator/gpio/gpio_shim_protocol.h"
#include "simulator/internal/sim_log.h"

namespace tp::sim {

namespace {

void copy_name(char (&dst)[GPIO_MAX_NAME_SIZE], const std::string& src) {
  std::memset(dst, 0, sizeof dst);
  std::strncpy(dst, src.c_str(), sizeof dst - 1);
}

template <class T>
T* resolve(UMockdevIoctlClient* client, UMockdevIoctlData** holder) {
  GError* err = nullptr;
  *holder = umockdev_ioctl_data_resolve(umockdev_ioctl_client_get_arg(client), 0, sizeof(T), &err);
  if (err) g_error_free(err);
  return *holder ? reinterpret_cast<T*>((*holder)->data) : nullptr;
}

}  // namespace

GpioChip::GpioChip(UMockdevTestbed* testbed, std::recursive_mutex& lock, int index, std::string label,
                   std::vector<GpioLineSpec> lines, EdgeFn on_edge)
    : testbed_(testbed), lock_(lock), index_(index), label_(std::move(label)), on_edge_(std::move(on_edge)) {
  devnode_ = "/dev/gpiochip" + std::to_string(index);
  for (auto& spec : lines) {
    Line l;
    l.spec = std::move(spec);
    lines_.push_back(std::move(l));
  }
}

GpioChip::~GpioChip() {
  if (handler_) g_object_unref(handler_);
}

Status GpioChip::plug() {
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(on_ioctl), this);
  g_signal_connect(handler_, "client-vanished", G_CALLBACK(on_vanished), this);
  GError* err = nullptr;
  if (!umockdev_testbed_attach_ioctl(testbed_, devnode_.c_str(), handler_, &err)) {
    std::string msg = err ? err->message : "unknown error";
    if (err) g_error_free(err);
    return fail(ErrorCode::kTestbed, devnode_ + ": attaching the ioctl handler: " + msg);
  }
  const std::string name = "gpiochip" + std::to_string(index_);
  const std::string syspath = "/devices/platform/tp-cutting-table/" + name;
  const std::string text = "P: " + syspath + "\nN: " + name + "\nE: SUBSYSTEM=gpio\nE: DEVNAME=/dev/" + name +
                           "\nA: dev=254:" + std::to_string(index_) + "\\n\nA: label=" + label_ + "\\n\nA: ngpio=" +
                           std::to_string(lines_.size()) + "\\n\n";
  if (!umockdev_testbed_add_from_string(testbed_, text.c_str(), &err)) {
    std::string msg = err ? err->message : "unknown error";
    if (err) g_error_free(err);
    return fail(ErrorCode::kTestbed, devnode_ + ": adding the chip: " + msg);
  }
  // libgpiod checks the chip against /sys/bus/gpio/devices/<name>/dev, which umockdev does
  // not link for this subsystem: add the link a kernel would have.
  gchar* root = umockdev_testbed_get_sys_dir(testbed_);
  std::error_code ec;
  const std::filesystem::path bus = std::filesystem::path(root) / "bus/gpio/devices";
  std::filesystem::create_directories(bus, ec);
  std::filesystem::create_directory_symlink(std::filesystem::path("../../..") / syspath.substr(1), bus / name, ec);
  g_free(root);
  sim_log()->info("{}: {} lines ({})", devnode_, lines_.size(), label_);
  return {};
}

bool GpioChip::drive_input(const std::string& name, bool level) {
  for (auto& l : lines_)
    if (l.spec.name == name && !l.spec.output) {
      l.spec.level = level;
      return true;
    }
  return false;
}

bool GpioChip::level(const std::string& name) const {
  for (const auto& l : lines_)
    if (l.spec.name == name) return l.spec.level;
  return false;
}

void GpioChip::set_level(Line& line, bool level) {
  if (line.spec.level == level) return;
  line.spec.level = level;
  if (on_edge_) on_edge_(line.spec.name, level);
}

gboolean GpioChip::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  auto* chip = static_cast<GpioChip*>(self);
  std::lock_guard guard(chip->lock_);
  chip->handle(client);
  return TRUE;
}

void GpioChip::on_vanished(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  auto* chip = static_cast<GpioChip*>(self);
  std::lock_guard guard(chip->lock_);
  // A process that dies (even by SIGKILL) closes its chip fd too: its line handles go back.
  std::vector<std::uint32_t> owned;
  for (const auto& [id, h] : chip->handles_)
    if (h.requester == client) owned.push_back(id);
  for (std::uint32_t id : owned) chip->release(id);
  auto it = chip->bound_.find(client);
  if (it == chip->bound_.end()) return;
  // Closing a line handle's fd gives its lines back, as the kernel does.
  chip->release(it->second);
  chip->bound_.erase(it);
}

void GpioChip::release(std::uint32_t handle) {
  auto it = handles_.find(handle);
  if (it == handles_.end()) return;
  for (std::uint32_t off : it->second.offsets) {
    lines_[off].requested = false;
    lines_[off].consumer.clear();
    lines_[off].handle = 0;
  }
  if (it->second.requester) g_object_unref(it->second.requester);
  handles_.erase(it);
}

void GpioChip::handle(UMockdevIoctlClient* client) {
  const unsigned long request = umockdev_ioctl_client_get_request(client);
  if (request == GPIO_GET_CHIPINFO_IOCTL) {
    UMockdevIoctlData* holder = nullptr;
    auto* info = resolve<gpiochip_info>(client, &holder);
    if (!info) return umockdev_ioctl_client_complete(client, -1, EFAULT);
    copy_name(info->name, "gpiochip" + std::to_string(index_));
    copy_name(info->label, label_);
    info->lines = static_cast<__u32>(lines_.size());
    g_object_unref(holder);
    return umockdev_ioctl_client_complete(client, 0, 0);
  }
  if (request == GPIO_GET_LINEINFO_IOCTL) return line_info(client);
  if (request == GPIO_GET_LINEHANDLE_IOCTL) return request_handle(client);
  if (request == TP_GPIO_BIND_HANDLE_IOCTL) return bind(client);
  if (request == TP_GPIO_RELEASE_HANDLE_IOCTL) {
    if (auto b = bound_.find(client); b != bound_.end()) {
      release(b->second);
      bound_.erase(b);
    }
    return umockdev_ioctl_client_complete(client, 0, 0);
  }
  if (request == GPIOHANDLE_GET_LINE_VALUES_IOCTL) return values(client, false);
  if (request == GPIOHANDLE_SET_LINE_VALUES_IOCTL) return values(client, true);
  // Line events, config changes and the v2 uAPI are not emulated.
  umockdev_ioctl_client_complete(client, -1, ENOTTY);
}

void GpioChip::line_info(UMockdevIoctlClient* client) {
  UMockdevIoctlData* holder = nullptr;
  auto* info = resolve<gpioline_info>(client, &holder);
  if (!info) return umockdev_ioctl_client_complete(client, -1, EFAULT);
  if (info->line_offset >= lines_.size()) {
    g_object_unref(holder);
    return umockdev_ioctl_client_complete(client, -1, EINVAL);
  }
  const Line& l = lines_[info->line_offset];
  info->flags = 0;
  if (l.requested) info->flags |= GPIOLINE_FLAG_KERNEL;
  if (l.requested ? l.requested_output : l.spec.output) info->flags |= GPIOLINE_FLAG_IS_OUT;
  if (l.requested && l.active_low) info->flags |= GPIOLINE_FLAG_ACTIVE_LOW;
  copy_name(info->name, l.spec.name);
  copy_name(info->consumer, l.consumer);
  g_object_unref(holder);
  umockdev_ioctl_client_complete(client, 0, 0);
}

void GpioChip::request_handle(UMockdevIoctlClient* client) {
  UMockdevIoctlData* holder = nullptr;
  auto* req = resolve<gpiohandle_request>(client, &holder);
  if (!req) return umockdev_ioctl_client_complete(client, -1, EFAULT);
  auto done = [&](int result, int err) {
    g_object_unref(holder);
    umockdev_ioctl_client_complete(client, result, err);
  };
  const bool out = req->flags & GPIOHANDLE_REQUEST_OUTPUT;
  const bool in = req->flags & GPIOHANDLE_REQUEST_INPUT;
  if (req->lines == 0 || req->lines > GPIOHANDLES_MAX || (out && in)) return done(-1, EINVAL);
  // Lines of a process that died (SIGKILL) without its connection being seen to vanish go back.
  std::vector<std::uint32_t> stale;
  for (const auto& [id, h] : handles_)
    if (h.requester && !umockdev_ioctl_client_get_connected(h.requester)) stale.push_back(id);
  for (std::uint32_t id : stale) release(id);
  for (__u32 i = 0; i < req->lines; ++i) {
    if (req->lineoffsets[i] >= lines_.size()) return done(-1, EINVAL);
    if (lines_[req->lineoffsets[i]].requested) return done(-1, EBUSY);
  }
  const std::uint32_t id = next_handle_++;
  Handle h;
  h.output = out;
  h.requester = UMOCKDEV_IOCTL_CLIENT(g_object_ref(client));
  for (__u32 i = 0; i < req->lines; ++i) {
    Line& l = lines_[req->lineoffsets[i]];
    h.offsets.push_back(req->lineoffsets[i]);
    l.requested = true;
    l.requested_output = out;
    l.active_low = req->flags & GPIOHANDLE_REQUEST_ACTIVE_LOW;
    l.consumer = std::string(req->consumer_label, strnlen(req->consumer_label, sizeof req->consumer_label));
    l.handle = id;
    if (out) set_level(l, (req->default_values[i] != 0) != l.active_low);
  }
  handles_[id] = std::move(h);
  // The kernel would return a new fd; the client's preload shim turns this marker into one.
  req->fd = static_cast<int>(TP_GPIO_HANDLE_MARKER + id);
  done(0, 0);
}

void GpioChip::bind(UMockdevIoctlClient* client) {
  UMockdevIoctlData* holder = nullptr;
  auto* id = resolve<__u32>(client, &holder);
  if (!id) return umockdev_ioctl_client_complete(client, -1, EFAULT);
  const std::uint32_t h = *id;
  g_object_unref(holder);
  if (!handles_.count(h)) return umockdev_ioctl_client_complete(client, -1, EINVAL);
  bound_[client] = h;
  umockdev_ioctl_client_complete(client, 0, 0);
}

void GpioChip::values(UMockdevIoctlClient* client, bool set) {
  auto b = bound_.find(client);
  // Values are only reachable through a line handle's fd.
  if (b == bound_.end()) return umockdev_ioctl_client_complete(client, -1, ENOTTY);
  auto h = handles_.find(b->second);
  if (h == handles_.end()) return umockdev_ioctl_client_complete(client, -1, EBADF);
  if (set && !h->second.output) return umockdev_ioctl_client_complete(client, -1, EPERM);
  UMockdevIoctlData* holder = nullptr;
  auto* data = resolve<gpiohandle_data>(client, &holder);
  if (!data) return umockdev_ioctl_client_complete(client, -1, EFAULT);
  for (std::size_t i = 0; i < h->second.offsets.size(); ++i) {
    Line& l = lines_[h->second.offsets[i]];
    if (set) set_level(l, (data->values[i] != 0) != l.active_low);
    else data->values[i] = static_cast<__u8>(l.spec.level != l.active_low ? 1 : 0);
  }
  g_object_unref(holder);
  umockdev_ioctl_client_complete(client, 0, 0);
}

}  // namespace tp::sim
