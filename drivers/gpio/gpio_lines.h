// drivers/gpio/gpio_lines.h: the cutting table's GPIO lines over libgpiod (v1 API): outputs
// cutter cue and notch mark, inputs cutter ready and emergency stop, by chip and line name.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "drivers/common/error.h"

namespace tp::drivers {

struct GpioConfig {
  std::string chip = "gpiochip0";  ///< chip name ("gpiochip0"), number ("0") or path ("/dev/gpiochip0")
  std::string cutter_cue = "cutter-cue";
  std::string notch_mark = "notch-mark";
  std::string cutter_ready = "cutter-ready";
  std::string emergency_stop = "emergency-stop";
  bool cutter_ready_active_low = false;
  bool emergency_stop_active_low = false;
  std::string consumer = "tp-print";  ///< label the kernel shows for our lines
};

enum class GpioOutput { kCutterCue, kNotchMark };

class GpioLines {
 public:
  /// Opens the chip and requests the four lines (outputs driven low). Fails with kNotFound
  /// naming the chip or the missing line, kBusy if a line is held by another consumer.
  [[nodiscard]] static Result<std::unique_ptr<GpioLines>> open(const GpioConfig& config);
  ~GpioLines();
  GpioLines(const GpioLines&) = delete;
  GpioLines& operator=(const GpioLines&) = delete;

  /// Drives an output line (true = active).
  [[nodiscard]] Status set(GpioOutput output, bool active);
  /// Drives the line active for `width`, then inactive again.
  [[nodiscard]] Status pulse(GpioOutput output, std::chrono::microseconds width);
  /// True when the cutter reports ready.
  [[nodiscard]] Result<bool> cutter_ready();
  /// True while the emergency stop is pressed.
  [[nodiscard]] Result<bool> emergency_stop();
  [[nodiscard]] const GpioConfig& config() const { return config_; }

  struct Impl;

 private:
  GpioLines(GpioConfig config, std::unique_ptr<Impl> impl);
  GpioConfig config_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::drivers
