// simulator/printsim/printer_sim.cpp: printsim's run: testbed, devices, firmware, scenario faults
// and the child command, all driven by one GLib main loop.
#include "simulator/printsim/printer_sim.h"

#include <glib-unix.h>
#include <glib.h>
#include <signal.h>
#include <sys/wait.h>
#include <umockdev.h>
#include <unistd.h>

#include <memory>
#include <mutex>

#include "device/firmware/controller.h"
#include "device/model/printer_model_file.h"
#include "simulator/internal/gpio_chip.h"
#include "simulator/internal/sim_log.h"
#include "simulator/internal/usb_printer_device.h"
#include "simulator/printsim/job_recorder.h"
#include "simulator/printsim/printer_memory.h"
#include "simulator/scenario/scenario.h"

namespace tp::sim {

namespace {

// The cutting table's lines on the emulated chip, in offset order.
std::vector<GpioLineSpec> cutting_table_lines() {
  return {{"cutter-cue", true, false},    {"notch-mark", true, false}, {"cutter-ready", false, true},
          {"emergency-stop", false, false}, {"spare-4", false, false}, {"spare-5", false, false},
          {"spare-6", false, false},        {"spare-7", false, false}};
}

std::string shim_path() {
  if (const char* p = g_getenv("TP_PRINTSIM_SHIM")) return p;
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return {};
  exe[n] = 0;
  const std::filesystem::path dir = std::filesystem::path(exe).parent_path();
  for (auto candidate : {dir / "../lib/libtp_gpio_preload.so", dir / "libtp_gpio_preload.so"})
    if (std::filesystem::exists(candidate)) return std::filesystem::weakly_canonical(candidate).string();
  return {};
}

struct Sim {
  SimOptions opt;
  // umockdev answers ioctls on its own thread; everything below is shared with it.
  std::recursive_mutex mu;
  UMockdevTestbed* testbed = nullptr;
  GMainLoop* loop = nullptr;
  gint64 t0 = 0;
  device::PrinterModel model;
  std::unique_ptr<device::PrinterController> controller;
  UsbCounters usb_counters;
  std::unique_ptr<JobRecorder> recorder;
  std::unique_ptr<UsbPrinterDevice> usb;
  std::vector<std::unique_ptr<UsbPrinterDevice>> retired;  // unplugged: still answer ENODEV
  std::unique_ptr<GpioChip> gpio;
  Scenario scenario;
  std::vector<bool> fired;
  int next_devnum = 2;
  bool job_seen = false;
  GPid child = 0;
  int exit_status = -1;

  std::int64_t now_us() const { return g_get_monotonic_time() - t0; }

  // Lets the printer catch up and hands its output to the host.
  void kick() {
    std::lock_guard guard(mu);
    controller->advance(now_us());
    if (usb) usb->service();
  }

  void replug() {
    usb = std::make_unique<UsbPrinterDevice>(testbed, *controller, mu, 1, next_devnum++, [this] { return now_us(); },
                                             usb_counters, opt.reap_hold_ms);
    if (auto s = usb->plug(); !s) sim_log()->error("{}", s.error().what());
  }

  // Runs `fn` on the main loop after `ms`, holding the lock.
  void schedule(std::int64_t ms, std::function<void()> fn) {
    auto* heap = new std::function<void()>([this, f = std::move(fn)] {
      std::lock_guard guard(mu);
      f();
    });
    g_timeout_add_full(G_PRIORITY_DEFAULT, static_cast<guint>(ms),
                       [](gpointer p) -> gboolean {
                         (*static_cast<std::function<void()>*>(p))();
                         return G_SOURCE_REMOVE;
                       },
                       heap, [](gpointer p) { delete static_cast<std::function<void()>*>(p); });
  }

  void pause_for(device::PrinterCondition c, std::int64_t ms) {
    controller->set_condition(c, true);
    schedule(ms, [this, c] {
      controller->set_condition(c, false);
      kick();
    });
  }

  void fire(std::size_t i) {
    if (fired[i]) return;
    fired[i] = true;
    const FaultSpec& f = scenario.faults[i];
    recorder->fault_injected(std::string(to_string(f.type)) + (f.at_swath ? " at swath " + std::to_string(*f.at_swath) : "") +
                             (f.duration_ms ? " for " + std::to_string(f.duration_ms) + " ms" : ""));
    sim_log()->info("fault: {}", to_string(f.type));
    switch (f.type) {
      case FaultType::kStall: if (usb) usb->inject_stall(); break;
      case FaultType::kDropFrame:
      case FaultType::kCorruptCrc: break;  // applied frame by frame in the receive hook
      case FaultType::kUnplug:
        // Not from inside a URB handler: pull the cable once the current request is answered.
        schedule(0, [this, ms = f.duration_ms] {
          if (!usb) return;
          usb->unplug();
          recorder->note_unplug();
          retired.push_back(std::move(usb));
          schedule(ms, [this] { replug(); });
        });
        break;
      case FaultType::kInkLow: pause_for(device::PrinterCondition::kInkLow, f.duration_ms); break;
      case FaultType::kCoverOpen: pause_for(device::PrinterCondition::kCoverOpen, f.duration_ms); break;
      case FaultType::kMediaOut: pause_for(device::PrinterCondition::kMediaOut, f.duration_ms); break;
      case FaultType::kMediaJam: controller->raise_fault(device::PrinterCondition::kMediaJam); break;
      case FaultType::kHeadStrike: controller->raise_fault(device::PrinterCondition::kHeadStrike); break;
      case FaultType::kCutterNotReady:
        gpio->drive_input("cutter-ready", false);
        schedule(f.duration_ms, [this] { gpio->drive_input("cutter-ready", true); });
        break;
      case FaultType::kBufferClear: controller->lose_job("buffer cleared by the operator"); break;
      case FaultType::kPowerLoss:
        // The job and the buffer go at once; the USB device disappears with the power.
        controller->lose_job("power loss");
        schedule(0, [this, ms = f.duration_ms] {
          if (!usb) return;
          usb->unplug();
          controller->link_reset();
          recorder->note_unplug();
          retired.push_back(std::move(usb));
          schedule(ms, [this] { replug(); });
        });
        break;
      case FaultType::kEmergencyStop:
        gpio->drive_input("emergency-stop", true);
        controller->raise_fault(device::PrinterCondition::kEmergencyStop);
        if (f.duration_ms > 0) schedule(f.duration_ms, [this] { gpio->drive_input("emergency-stop", false); });
        break;
    }
  }

  static bool link_fault(FaultType t) { return t == FaultType::kStall || t == FaultType::kUnplug; }

  // What the printer keeps across a power loss goes to --state whenever it changes.
  void save_memory(const device::FirmwareEvent& e) {
    using K = device::FirmwareEventKind;
    if (!opt.state_file) return;
    if (e.kind != K::kJobBegin && e.kind != K::kSwathPrinted && e.kind != K::kFeed && e.kind != K::kStateChanged) return;
    if (auto s = save_printer_memory(*opt.state_file, controller->nonvolatile()); !s) sim_log()->error("{}", s.error().what());
  }

  void on_event(const device::FirmwareEvent& e) {
    recorder->firmware_event(e);
    save_memory(e);
    using K = device::FirmwareEventKind;
    if (e.kind == K::kJobBegin && !job_seen) {
      job_seen = true;
      for (std::size_t i = 0; i < scenario.faults.size(); ++i)
        if (scenario.faults[i].after_ms) schedule(*scenario.faults[i].after_ms, [this, i] { fire(i); kick(); });
    }
    for (std::size_t i = 0; i < scenario.faults.size(); ++i) {
      const FaultSpec& f = scenario.faults[i];
      if (!f.at_swath || *f.at_swath != e.swath || fired[i]) continue;
      if ((e.kind == K::kSwathHeader && link_fault(f.type)) || (e.kind == K::kSwathPrinting && !link_fault(f.type)))
        fire(i);
    }
  }

  device::RxFault on_frame(std::uint64_t n) {
    for (std::size_t i = 0; i < scenario.faults.size(); ++i) {
      const FaultSpec& f = scenario.faults[i];
      if (!f.at_frame || n < *f.at_frame || n >= *f.at_frame + f.count) continue;
      if (n == *f.at_frame) fire(i);
      return f.type == FaultType::kDropFrame ? device::RxFault::kDrop : device::RxFault::kCorrupt;
    }
    return device::RxFault::kNone;
  }
};

}  // namespace

Result<int> run_printsim(const SimOptions& options) {
  if (options.command.empty()) return fail(ErrorCode::kInvalidArgument, "printsim run: no command given after --");
  auto sim = std::make_unique<Sim>();
  sim->opt = options;
  sim->t0 = g_get_monotonic_time();
  if (options.printer_model) {
    auto m = device::load_printer_model(*options.printer_model);
    if (!m) return fail(ErrorCode::kInvalidArgument, m.error().message);
    sim->model = *m;
  }
  if (options.scenario) {
    auto s = load_scenario(*options.scenario);
    if (!s) return fail(s.error());
    sim->scenario = std::move(*s);
  }
  sim->fired.assign(sim->scenario.faults.size(), false);
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (!std::filesystem::is_directory(options.out_dir))
    return fail(ErrorCode::kOutput, options.out_dir.string() + ": cannot create the output folder");

  Sim& s = *sim;
  device::FirmwareOptions fo;
  fo.speed = options.speed;
  s.controller = std::make_unique<device::PrinterController>(s.model, nullptr, fo);
  if (options.state_file) {
    // Power-on: a job the memory says was open was lost with the power.
    auto nv = load_printer_memory(*options.state_file);
    if (!nv) return fail(nv.error());
    s.controller->restore(*nv);
  }
  s.recorder = std::make_unique<JobRecorder>(RecorderOptions{options.out_dir, options.job_dirs, options.fabric,
                                                             options.state_file.has_value()},
                                             *s.controller, s.usb_counters,
                                             [&s] { return static_cast<double>(s.now_us()) / 1e6; });
  s.controller->set_sink(s.recorder.get());
  s.controller->set_observer([&s](const device::FirmwareEvent& e) { s.on_event(e); });
  s.controller->set_rx_fault_hook([&s](std::uint64_t n, const device::FrameHeader&) { return s.on_frame(n); });

  // The testbed sets UMOCKDEV_DIR in our environment; the child inherits it.
  s.testbed = umockdev_testbed_new();
  s.loop = g_main_loop_new(nullptr, FALSE);
  auto cleanup = [&s] {
    s.usb.reset();
    s.retired.clear();
    s.gpio.reset();
    if (s.testbed) g_object_unref(s.testbed);
    if (s.loop) g_main_loop_unref(s.loop);
    s.testbed = nullptr;
    s.loop = nullptr;
  };
  s.replug();
  if (!s.usb->plugged()) {
    cleanup();
    return fail(ErrorCode::kTestbed, "could not add the emulated USB printer to the testbed");
  }
  s.gpio = std::make_unique<GpioChip>(s.testbed, s.mu, 0, "tp-cutting-table", cutting_table_lines(),
                                      [&s](const std::string& line, bool level) { s.recorder->gpio_edge(line, level); });
  if (auto st = s.gpio->plug(); !st) {
    cleanup();
    return fail(st.error());
  }

  // The command runs with umockdev's preload (and our line-handle shim ahead of it).
  gchar** env = g_get_environ();
  std::string preload = "libumockdev-preload.so.0";
  const std::string shim = shim_path();
  if (shim.empty()) sim_log()->warn("libtp_gpio_preload.so not found: GPIO line requests will fail in the command");
  else preload = shim + ":" + preload;
  if (const char* old = g_environ_getenv(env, "LD_PRELOAD"); old && *old) preload += std::string(":") + old;
  env = g_environ_setenv(env, "LD_PRELOAD", preload.c_str(), TRUE);
  env = g_environ_setenv(env, kPrintsimEnv, std::filesystem::absolute(options.out_dir).c_str(), TRUE);
  env = g_environ_setenv(env, "TP_PRINTSIM_GPIOCHIP", s.gpio->devnode().c_str(), TRUE);
  std::vector<gchar*> argv;
  for (const auto& a : options.command) argv.push_back(const_cast<gchar*>(a.c_str()));
  argv.push_back(nullptr);
  GError* err = nullptr;
  const gboolean spawned = g_spawn_async(nullptr, argv.data(), env,
                                         static_cast<GSpawnFlags>(G_SPAWN_SEARCH_PATH | G_SPAWN_DO_NOT_REAP_CHILD |
                                                                  G_SPAWN_CHILD_INHERITS_STDIN),
                                         nullptr, nullptr, &s.child, &err);
  g_strfreev(env);
  if (!spawned) {
    std::string msg = err ? err->message : "unknown error";
    if (err) g_error_free(err);
    cleanup();
    return fail(ErrorCode::kChild, "cannot run '" + options.command.front() + "': " + msg);
  }
  g_child_watch_add(
      s.child,
      [](GPid pid, gint status, gpointer p) {
        auto* sp = static_cast<Sim*>(p);
        sp->exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        g_spawn_close_pid(pid);
        g_main_loop_quit(sp->loop);
      },
      &s);
  // Stopping printsim stops the command first, so its outputs still get written.
  for (int sig : {SIGINT, SIGTERM})
    g_unix_signal_add(
        sig,
        [](gpointer p) -> gboolean {
          auto* sp = static_cast<Sim*>(p);
          if (sp->child) kill(sp->child, SIGTERM);
          return G_SOURCE_CONTINUE;
        },
        &s);
  // The engine's clock: timed passes and feeds finish, statuses reach the host.
  g_timeout_add(
      5,
      [](gpointer p) -> gboolean {
        static_cast<Sim*>(p)->kick();
        return G_SOURCE_CONTINUE;
      },
      &s);
  g_main_loop_run(s.loop);

  std::unique_lock guard(s.mu);
  s.recorder->close();
  const std::string output_error = s.recorder->error();
  guard.unlock();
  const int status = s.exit_status;
  cleanup();
  if (!output_error.empty()) return fail(ErrorCode::kOutput, output_error);
  return status;
}

}  // namespace tp::sim
