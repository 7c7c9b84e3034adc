// host/app/printctl/cmd_link.cpp: printer link tools: `printctl wire-dump <recording>` decodes a
// wire recording to text; the hidden `printctl link-job` runs a synthetic job (no RIP) through
// the real print session, USB and GPIO drivers, under printsim, for the link's scenario tests.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "device/protocol/describe.h"
#include "device/protocol/recording.h"
#include "host/app/printctl/commands.h"
#include "host/session/print_session.h"
#include "host/session/sim_reexec.h"
#include "host/session/synthetic_run.h"

namespace tp::host::cli {

namespace {

namespace fs = std::filesystem;

struct LinkJobArgs {
  SyntheticRunOptions run;
  std::string out = "out/link-job";
  std::string scenario;
  std::string printer_model;
  std::string result;
  std::string record;
  bool no_gpio = false;
  long long reconnect_timeout_ms = PrinterConfig{}.reconnect_timeout.count();
  long long cutter_timeout_ms = 10000;
};

nlohmann::json result_json(const SyntheticRunResult* r, const PrintSession* session, std::uint32_t acked,
                           const std::string& error) {
  nlohmann::json j;
  j["ok"] = error.empty();
  j["error"] = error;
  j["swaths_acked"] = acked;
  if (session) {
    const SessionStats& s = session->stats();
    j["session"] = {{"swaths_sent", s.swaths_sent},         {"swaths_skipped", s.swaths_skipped},
                    {"swaths_acked", s.swaths_acked},       {"swaths_resent", s.swaths_resent},
                    {"reconnects", s.reconnects},           {"recovery_ms_last", s.recovery_ms_last},
                    {"recovery_ms_max", s.recovery_ms_max}, {"credit_wait_s", s.credit_wait_s},
                    {"pause_s", s.pause_s}};
  }
  if (r) {
    const auto& rep = r->job.report;
    j["swaths"] = r->swaths;
    j["data_bytes"] = r->data_bytes;
    j["stream_s"] = r->stream_s;
    j["throughput_MBps"] = r->throughput_MBps;
    j["report"] = {{"swaths_printed", rep.swaths_printed}, {"feed_travel_um", rep.feed_travel_um},
                   {"print_time_s", static_cast<double>(rep.print_time_us) / 1e6}, {"cues_fired", rep.cues_fired},
                   {"overruns", rep.overruns},             {"drops_per_ink", rep.drops_per_ink}};
    const auto& l = r->job.stats.link;
    j["link"] = {{"frames_sent", l.frames_sent}, {"frames_resent", l.frames_resent}, {"naks_seen", l.naks_seen},
                 {"timeouts", l.timeouts},       {"rx_errors", l.rx_errors}};
    nlohmann::json cues = nlohmann::json::array();
    for (const auto& c : r->job.cues)
      cues.push_back({{"id", c.id}, {"kind", std::string(device::to_string(c.kind))}, {"position_um", c.position_um},
                      {"fired", c.fired}, {"fired_at_um", c.fired_at_um}});
    j["cues"] = cues;
  }
  return j;
}

void run_link_job(const LinkJobArgs& a) {
  SimReexec sim;
  sim.out_dir = fs::absolute(a.out);
  if (!a.scenario.empty()) sim.scenario = fs::absolute(a.scenario);
  if (!a.printer_model.empty()) sim.printer_model = fs::absolute(a.printer_model);
  if (auto s = reexec_under_printsim(sim); !s) {
    std::fprintf(stderr, "%s\n", s.error().message.c_str());
    throw CLI::RuntimeError(2);
  }
  PrinterConfig cfg;
  cfg.use_gpio = !a.no_gpio;
  cfg.reconnect_timeout = std::chrono::milliseconds(a.reconnect_timeout_ms);
  cfg.cutter_ready_timeout = std::chrono::milliseconds(a.cutter_timeout_ms);
  if (!a.record.empty()) cfg.wire_recording = a.record;
  std::uint32_t acked = 0;
  std::string error;
  std::optional<SyntheticRunResult> result;
  auto session = PrintSession::open(cfg);
  if (!session) {
    error = session.error().message;
  } else {
    (*session)->on_swath_acked([&](std::uint32_t) { ++acked; });
    geometry::CancelToken cancel;
    auto r = run_synthetic_job(**session, a.run, cancel);
    if (r) result = std::move(*r);
    else error = r.error().message;
  }
  const nlohmann::json j = result_json(result ? &*result : nullptr, session ? session->get() : nullptr, acked, error);
  if (!a.result.empty()) std::ofstream(a.result) << j.dump(2) << "\n";
  if (!error.empty()) {
    std::fprintf(stderr, "link-job: %s\n", error.c_str());
    throw CLI::RuntimeError(1);
  }
  std::printf("swaths=%u\nswaths_acked=%u\nswaths_printed=%u\nreconnects=%u\nthroughput_MBps=%.2f\n", result->swaths,
              acked, result->job.report.swaths_printed, result->job.stats.reconnects, result->throughput_MBps);
}

}  // namespace

void register_link_commands(CLI::App& app) {
  static std::string dump_path;
  static bool dump_times = false;
  CLI::App* dump = app.add_subcommand("wire-dump", "Decode a printer-link recording to text, one line per frame");
  dump->add_option("recording", dump_path, "Recording written by a session with wire recording on")->required();
  dump->add_flag("--time", dump_times, "Prefix each line with its time in seconds");
  dump->callback([] {
    auto records = device::read_recording(dump_path);
    if (!records) {
      std::fprintf(stderr, "%s\n", records.error().message.c_str());
      throw CLI::RuntimeError(1);
    }
    const std::string text = device::dump_recording(*records, device::DumpOptions{dump_times});
    std::fwrite(text.data(), 1, text.size(), stdout);
  });

  static LinkJobArgs a;
  CLI::App* job = app.add_subcommand("link-job", "Run a synthetic job through the printer link (tests)");
  job->group("");  // hidden: a tool for the link's scenario tests, not for operators
  job->add_option("--swaths", a.run.job.swaths, "Swaths in the job");
  job->add_option("--width", a.run.job.width_px, "Printed width of each swath, pixels");
  job->add_option("--rows", a.run.job.rows, "Rows per swath (0: the printer's nozzles)");
  job->add_option("--cue-every", a.run.job.cue_every, "A cut cue after every N swaths (0: none)");
  job->add_flag("--noise", a.run.job.noise, "Noise instead of bands");
  job->add_option("--job-id", a.run.job_id, "Job id");
  job->add_option("--name", a.run.name, "Job name");
  job->add_option("--first-swath", a.run.first_swath, "Resume from this swath");
  job->add_option("--out", a.out, "printsim output folder");
  job->add_option("--scenario", a.scenario, "printsim fault scenario");
  job->add_option("--printer-model", a.printer_model, "printsim printer model file");
  job->add_option("--result", a.result, "Write the outcome as JSON here");
  job->add_option("--record", a.record, "Record the link traffic here (for wire-dump)");
  job->add_flag("--no-gpio", a.no_gpio, "Do not use the cutting table's GPIO lines");
  job->add_option("--reconnect-timeout-ms", a.reconnect_timeout_ms, "How long an unplugged printer may stay away");
  job->add_option("--cutter-timeout-ms", a.cutter_timeout_ms, "How long to wait for cutter-ready at a cue");
  job->callback([] { run_link_job(a); });
}

}  // namespace tp::host::cli
