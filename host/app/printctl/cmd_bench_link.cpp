// host/app/printctl/cmd_bench_link.cpp: `printctl bench link --seconds N`: streams screened-noise
// swaths to the simulated printer through the real print session, libusb and umockdev path
// and prints key=value figures: throughput against the ~53 MB/s USB 2.0 bulk limit, swaths
// sent and acknowledged, and (with --unplug-after-swath) the time to recover from an unplug.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "host/app/printctl/commands.h"
#include "host/session/print_session.h"
#include "host/session/sim_reexec.h"
#include "host/session/synthetic_run.h"

namespace tp::host::cli {

namespace {

namespace fs = std::filesystem;

// USB 2.0 high speed: 13 bulk packets of 512 bytes per 125 us microframe.
constexpr double kUsb2BulkLimitMBps = 13 * 512 * 8000 / 1e6;

struct BenchArgs {
  double seconds = 5;
  std::uint32_t width_px = 8000;
  std::uint32_t rows = 0;
  long long unplug_after_swath = -1;
  long long unplug_ms = 500;
  bool fabric = false;
  std::string out;
};

void run_bench(const BenchArgs& a) {
  const fs::path out = a.out.empty() ? fs::temp_directory_path() / ("tp-bench-link-" + std::to_string(::getpid()))
                                     : fs::absolute(a.out);
  SimReexec sim;
  sim.out_dir = out;
  sim.fabric = a.fabric;
  if (a.unplug_after_swath >= 0 && !under_printsim()) {
    fs::create_directories(out);
    sim.scenario = out / "unplug.json";
    std::ofstream(*sim.scenario) << "{\"faults\": [{\"type\": \"unplug\", \"at_swath\": " << a.unplug_after_swath
                                 << ", \"duration_ms\": " << a.unplug_ms << "}]}\n";
  }
  if (auto s = reexec_under_printsim(sim); !s) {
    std::fprintf(stderr, "%s\n", s.error().message.c_str());
    throw CLI::RuntimeError(2);
  }
  PrinterConfig cfg;
  auto session = PrintSession::open(cfg);
  if (!session) {
    std::fprintf(stderr, "bench link: %s\n", session.error().message.c_str());
    throw CLI::RuntimeError(1);
  }
  std::uint32_t acked = 0;
  (*session)->on_swath_acked([&](std::uint32_t) { ++acked; });
  SyntheticRunOptions o;
  o.seconds = a.seconds;
  o.name = "bench-link";
  o.job.noise = true;
  o.job.cue_every = 0;
  o.job.width_px = a.width_px;
  o.job.rows = a.rows;
  geometry::CancelToken cancel;
  auto r = run_synthetic_job(**session, o, cancel);
  if (!r) {
    std::fprintf(stderr, "bench link: %s\n", r.error().message.c_str());
    throw CLI::RuntimeError(1);
  }
  const SessionStats& st = r->job.stats;
  std::printf("bench=link\n");
  std::printf("printer=%s\n", (*session)->describe().c_str());
  std::printf("seconds=%.2f\n", r->stream_s);
  std::printf("swath_MB=%.2f\n", r->swaths ? static_cast<double>(r->data_bytes) / r->swaths / 1e6 : 0.0);
  std::printf("swaths_sent=%u\n", st.swaths_sent);
  std::printf("swaths_acked=%u\n", acked);
  std::printf("swaths_printed=%u\n", r->job.report.swaths_printed);
  std::printf("data_MB=%.1f\n", static_cast<double>(r->data_bytes) / 1e6);
  std::printf("throughput_MBps=%.1f\n", r->throughput_MBps);
  std::printf("usb2_bulk_limit_MBps=%.1f\n", kUsb2BulkLimitMBps);
  std::printf("fraction_of_usb2=%.2f\n", r->throughput_MBps / kUsb2BulkLimitMBps);
  std::printf("wire_MB=%.1f\n", static_cast<double>(st.link.bytes_sent) / 1e6);
  std::printf("frames_sent=%llu\n", static_cast<unsigned long long>(st.link.frames_sent));
  std::printf("frames_resent=%llu\n", static_cast<unsigned long long>(st.link.frames_resent));
  std::printf("credit_wait_s=%.2f\n", st.credit_wait_s);
  std::printf("printer_print_time_s=%.1f\n", static_cast<double>(r->job.report.print_time_us) / 1e6);
  std::printf("reconnects=%u\n", st.reconnects);
  if (a.unplug_after_swath >= 0) {
    std::printf("unplug_ms=%lld\n", a.unplug_ms);
    std::printf("recovery_ms=%.0f\n", st.recovery_ms_max);
    std::printf("recovery_overhead_ms=%.0f\n", st.recovery_ms_max - static_cast<double>(a.unplug_ms));
    std::printf("swaths_resent=%u\n", st.swaths_resent);
  }
}

}  // namespace

void register_bench_link(CLI::App& bench) {
  static BenchArgs a;
  CLI::App* link = bench.add_subcommand("link", "Swath throughput to the simulated printer through libusb");
  link->add_option("--seconds", a.seconds, "How long to stream")->check(CLI::Range(0.1, 3600.0));
  link->add_option("--width", a.width_px, "Printed width of each swath, pixels");
  link->add_option("--rows", a.rows, "Rows per swath (0: the printer's nozzles per ink)");
  link->add_option("--unplug-after-swath", a.unplug_after_swath, "Pull the USB cable when this swath arrives");
  link->add_option("--unplug-ms", a.unplug_ms, "How long the cable stays out");
  link->add_flag("--fabric", a.fabric, "Let printsim lay drops and write images too");
  link->add_option("--out", a.out, "printsim output folder (default: a temporary folder)");
  link->callback([] { run_bench(a); });
}

}  // namespace tp::host::cli
