// drivers/gpio/gpio_lines.cpp: GPIO lines of the cutting table through libgpiod 1.x.
#include "drivers/gpio/gpio_lines.h"

#include <gpiod.h>

#include <cerrno>
#include <cstring>
#include <thread>

#include "drivers/common/internal/log.h"

namespace tp::drivers {

struct GpioLines::Impl {
  gpiod_chip* chip = nullptr;
  gpiod_line* cue = nullptr;
  gpiod_line* notch = nullptr;
  gpiod_line* ready = nullptr;
  gpiod_line* estop = nullptr;

  ~Impl() {
    // Releasing a line hands it back to the kernel; closing the chip releases what is left.
    for (gpiod_line* l : {cue, notch, ready, estop})
      if (l && gpiod_line_is_requested(l)) gpiod_line_release(l);
    if (chip) gpiod_chip_close(chip);
  }
};

namespace {

Result<gpiod_line*> request(gpiod_chip* chip, const std::string& chip_name, const std::string& name, bool output,
                            bool active_low, const std::string& consumer) {
  gpiod_line* line = gpiod_chip_find_line(chip, name.c_str());
  if (!line)
    return fail(ErrorCode::kNotFound, "GPIO chip '" + chip_name + "' has no line named '" + name + "'");
  const int flags = active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
  const int r = output ? gpiod_line_request_output_flags(line, consumer.c_str(), flags, 0)
                       : gpiod_line_request_input_flags(line, consumer.c_str(), flags);
  if (r != 0) {
    const int err = errno;
    return fail(err == EBUSY ? ErrorCode::kBusy : ErrorCode::kIo,
                "GPIO line '" + name + "' on '" + chip_name + "': request as " + (output ? "output" : "input") +
                    " failed: " + std::strerror(err));
  }
  return line;
}

}  // namespace

GpioLines::GpioLines(GpioConfig config, std::unique_ptr<Impl> impl)
    : config_(std::move(config)), impl_(std::move(impl)) {}

GpioLines::~GpioLines() = default;

Result<std::unique_ptr<GpioLines>> GpioLines::open(const GpioConfig& config) {
  auto impl = std::make_unique<Impl>();
  impl->chip = gpiod_chip_open_lookup(config.chip.c_str());
  if (!impl->chip)
    return fail(ErrorCode::kNotFound, "GPIO chip '" + config.chip + "': cannot open: " + std::strerror(errno));
  auto cue = request(impl->chip, config.chip, config.cutter_cue, true, false, config.consumer);
  if (!cue) return fail(cue.error());
  impl->cue = *cue;
  auto notch = request(impl->chip, config.chip, config.notch_mark, true, false, config.consumer);
  if (!notch) return fail(notch.error());
  impl->notch = *notch;
  auto ready = request(impl->chip, config.chip, config.cutter_ready, false, config.cutter_ready_active_low, config.consumer);
  if (!ready) return fail(ready.error());
  impl->ready = *ready;
  auto estop = request(impl->chip, config.chip, config.emergency_stop, false, config.emergency_stop_active_low,
                       config.consumer);
  if (!estop) return fail(estop.error());
  impl->estop = *estop;
  drivers_log()->info("GPIO '{}': cue '{}', notch '{}', ready '{}', e-stop '{}'", config.chip, config.cutter_cue,
                      config.notch_mark, config.cutter_ready, config.emergency_stop);
  return std::unique_ptr<GpioLines>(new GpioLines(config, std::move(impl)));
}

Status GpioLines::set(GpioOutput output, bool active) {
  gpiod_line* line = output == GpioOutput::kCutterCue ? impl_->cue : impl_->notch;
  if (gpiod_line_set_value(line, active ? 1 : 0) != 0)
    return fail(ErrorCode::kIo, "GPIO line '" + std::string(gpiod_line_name(line) ? gpiod_line_name(line) : "?") +
                                    "': set value failed: " + std::strerror(errno));
  return {};
}

Status GpioLines::pulse(GpioOutput output, std::chrono::microseconds width) {
  if (auto s = set(output, true); !s) return s;
  std::this_thread::sleep_for(width);
  return set(output, false);
}

Result<bool> GpioLines::cutter_ready() {
  const int v = gpiod_line_get_value(impl_->ready);
  if (v < 0) return fail(ErrorCode::kIo, "GPIO line '" + config_.cutter_ready + "': read failed: " + std::strerror(errno));
  return v == 1;
}

Result<bool> GpioLines::emergency_stop() {
  const int v = gpiod_line_get_value(impl_->estop);
  if (v < 0)
    return fail(ErrorCode::kIo, "GPIO line '" + config_.emergency_stop + "': read failed: " + std::strerror(errno));
  return v == 1;
}

}  // namespace tp::drivers
