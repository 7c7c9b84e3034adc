// simulator/internal/gpio_chip.h: an emulated GPIO character device (/dev/gpiochipN) in a
// umockdev testbed with named lines: answers chip info, line info, line handle requests and
// line values (GPIO v1 uAPI, as libgpiod 1.x uses it), and reports every output edge.
#pragma once

#include <umockdev.h>

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "simulator/common/error.h"

namespace tp::sim {

struct GpioLineSpec {
  std::string name;
  bool output = false;  ///< the cutting table drives inputs; the host drives outputs
  bool level = false;   ///< initial physical level
};

class GpioChip {
 public:
  /// Called with the line name and its new physical level on every output edge.
  using EdgeFn = std::function<void(const std::string& line, bool level)>;

  /// `lock` guards the chip against printsim's main loop (umockdev answers on its own thread).
  GpioChip(UMockdevTestbed* testbed, std::recursive_mutex& lock, int index, std::string label,
           std::vector<GpioLineSpec> lines, EdgeFn on_edge);
  ~GpioChip();
  GpioChip(const GpioChip&) = delete;
  GpioChip& operator=(const GpioChip&) = delete;

  /// Adds /dev/gpiochip<index> and its sysfs entries to the testbed and starts answering.
  [[nodiscard]] Status plug();
  /// Sets an input line's physical level (the cutting table's side). False if no such line.
  bool drive_input(const std::string& name, bool level);
  /// Physical level of a line (outputs as last driven).
  [[nodiscard]] bool level(const std::string& name) const;
  [[nodiscard]] const std::string& devnode() const { return devnode_; }

 private:
  struct Line {
    GpioLineSpec spec;
    bool requested = false;
    bool requested_output = false;
    bool active_low = false;
    std::string consumer;
    std::uint32_t handle = 0;
  };
  struct Handle {
    std::vector<std::uint32_t> offsets;
    UMockdevIoctlClient* requester = nullptr;  ///< the chip connection that asked for it
    bool output = false;
  };

  static gboolean on_ioctl(UMockdevIoctlBase* handler, UMockdevIoctlClient* client, gpointer self);
  static void on_vanished(UMockdevIoctlBase* handler, UMockdevIoctlClient* client, gpointer self);
  void handle(UMockdevIoctlClient* client);
  void line_info(UMockdevIoctlClient* client);
  void request_handle(UMockdevIoctlClient* client);
  void bind(UMockdevIoctlClient* client);
  void values(UMockdevIoctlClient* client, bool set);
  void release(std::uint32_t handle);
  void set_level(Line& line, bool level);

  UMockdevTestbed* testbed_;
  std::recursive_mutex& lock_;
  int index_;
  std::string label_;
  std::string devnode_;
  std::vector<Line> lines_;
  EdgeFn on_edge_;
  UMockdevIoctlBase* handler_ = nullptr;
  std::map<std::uint32_t, Handle> handles_;
  std::map<UMockdevIoctlClient*, std::uint32_t> bound_;
  std::uint32_t next_handle_ = 1;
};

}  // namespace tp::sim
