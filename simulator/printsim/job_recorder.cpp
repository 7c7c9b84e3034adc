// simulator/printsim/job_recorder.cpp: per-job fabric, logs and printer.json.
#include "simulator/printsim/job_recorder.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "simulator/internal/sim_log.h"
#include "simulator/internal/usb_printer_device.h"

namespace tp::sim {

namespace {

// Job names become folder names: keep them to a safe alphabet.
std::string safe_name(const std::string& name) {
  std::string s;
  for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  if (s.empty() || s == "." || s == "..") s = "job";
  return s.substr(0, 100);
}

const char* event_name(device::FirmwareEventKind k) {
  switch (k) {
    case device::FirmwareEventKind::kJobBegin: return "job_begin";
    case device::FirmwareEventKind::kSwathHeader: return "swath_header";
    case device::FirmwareEventKind::kSwathCommitted: return "swath_committed";
    case device::FirmwareEventKind::kSwathPrinting: return "swath_printing";
    case device::FirmwareEventKind::kSwathPrinted: return "swath_printed";
    case device::FirmwareEventKind::kFeed: return "feed";
    case device::FirmwareEventKind::kCueReached: return "cue_reached";
    case device::FirmwareEventKind::kStateChanged: return "state";
    case device::FirmwareEventKind::kReject: return "reject";
    case device::FirmwareEventKind::kJobEnd: return "job_end";
  }
  return "unknown";
}

}  // namespace

JobRecorder::JobRecorder(RecorderOptions options, const device::PrinterController& controller, const UsbCounters& usb,
                         std::function<double()> clock_s)
    : options_(std::move(options)), controller_(controller), usb_(usb), clock_s_(std::move(clock_s)) {}

JobRecorder::~JobRecorder() {
  {
    std::lock_guard lock(writer_mu_);
    writer_stop_ = true;
  }
  writer_cv_.notify_all();
  if (writer_.joinable()) writer_.join();
}

std::string JobRecorder::error() const {
  std::lock_guard lock(writer_mu_);
  return error_;
}

void JobRecorder::write_async(std::function<void()> work) {
  {
    std::lock_guard lock(writer_mu_);
    if (!writer_.joinable()) writer_ = std::thread([this] { writer_loop(); });
    writer_queue_.push_back(std::move(work));
  }
  writer_cv_.notify_all();
}

void JobRecorder::writer_loop() {
  std::unique_lock lock(writer_mu_);
  for (;;) {
    writer_cv_.wait(lock, [&] { return writer_stop_ || !writer_queue_.empty(); });
    if (writer_queue_.empty()) return;
    auto work = std::move(writer_queue_.front());
    lock.unlock();
    work();
    lock.lock();
    writer_queue_.pop_front();
    writer_cv_.notify_all();
  }
}

std::filesystem::path JobRecorder::job_dir(const device::JobBeginMsg& job) const {
  if (!options_.job_dirs) return options_.out_dir;
  // By id first: two jobs with one name must not overwrite each other's fabric.
  return options_.out_dir / (std::to_string(job.job_id) + "-" + safe_name(job.name.empty() ? "job" : job.name));
}

void JobRecorder::job_started(const device::JobBeginMsg& job, bool resumed) {
  if (resumed) {
    ++resumes_;
    return;
  }
  if (active_ && lost_ && job.job_id == job_.job_id) {
    // The printer lost the job and the host reopened it: printing goes on on the same fabric.
    lost_ = false;
    ++resumes_;
    return;
  }
  if (active_) finish(controller_.current_report(), lost_ ? "lost" : "incomplete");
  active_ = true;
  lost_ = false;
  losses_ = 0;
  job_ = job;
  started_s_ = clock_s_();
  resumes_ = 0;
  unplugs_ = 0;
  edges_.clear();
  events_.clear();
  faults_.clear();
  dir_ = job_dir(job);
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  canvas_.reset();
  if (!options_.fabric) return;
  const auto& m = controller_.model();
  FabricSpec spec;
  spec.width_px = job.fabric_width_px ? job.fabric_width_px
                                      : static_cast<std::uint32_t>(std::lround(m.print_width_mm * m.dpi_x / 25.4));
  for (const auto& ink : m.inks) spec.inks.push_back(ink.name);
  spec.dpi_x = m.dpi_x;
  spec.dpi_y = m.dpi_y;
  spec.bits_per_pixel = m.bits_per_pixel;
  spec.reach_rows = static_cast<std::int64_t>(m.nozzles_per_ink) * m.nozzle_pitch_rows;
  spec.columns_reversed = m.carriage_origin == device::CarriageOrigin::kRight;
  spec.look.fabric = m.fabric;
  for (const auto& ink : m.inks) spec.look.ink_strength.push_back(ink.strength);
  spec.look.drop_volume_pl = m.drop_volume_pl;
  spec.look.drop_coverage = m.drop_coverage;
  spec.look.yule_nielsen_n = m.yule_nielsen_n;
  auto canvas = FabricCanvas::create(spec, dir_ / ".fabric.scratch");
  if (!canvas) {
    sim_log()->error("{}", canvas.error().what());
    std::lock_guard lock(writer_mu_);
    if (error_.empty()) error_ = canvas.error().what();
    return;
  }
  canvas_ = std::move(*canvas);
  if (options_.persist) start_journal(job);
}

void JobRecorder::start_journal(const device::JobBeginMsg& job) {
  const std::filesystem::path path = dir_ / ".fabric.journal";
  journal_.reset();
  if (job.first_swath > 0) {
    // A job resumed after printsim itself stopped: the fabric it laid before is still there.
    std::uint32_t replayed = 0;
    auto j = FabricJournal::reopen(path, job.job_id, job.first_swath,
                                   [&](const device::SwathHeader& h, std::span<const std::uint8_t> raw) {
                                     canvas_->lay(h, raw, h.first_row);
                                     ++replayed;
                                   });
    if (j) {
      journal_ = std::move(*j);
      ++resumes_;
      events_.push_back(Event{clock_s_(), "fabric_resumed", job.first_swath, 0, controller_.fabric_pos_um(),
                              std::to_string(replayed) + " swaths already on the fabric"});
      return;
    }
    sim_log()->warn("{}", j.error().what());
  }
  auto j = FabricJournal::create(path, job.job_id);
  if (!j) {
    sim_log()->error("{}", j.error().what());
    return;
  }
  journal_ = std::move(*j);
}

void JobRecorder::swath_printed(const device::SwathHeader& header, std::span<const std::uint8_t> raw,
                                std::int64_t fabric_row) {
  if (canvas_) canvas_->lay(header, raw, fabric_row);
  if (journal_)
    if (auto s = journal_->append(header, raw); !s) {
      sim_log()->error("{}", s.error().what());
      journal_.reset();
    }
}

void JobRecorder::gpio_edge(const std::string& line, bool level) {
  edges_.push_back(Edge{line, level, clock_s_(), controller_.fabric_pos_um()});
  all_edges_.push_back(edges_.back());
}

void JobRecorder::firmware_event(const device::FirmwareEvent& e) {
  using K = device::FirmwareEventKind;
  // Per-frame and per-feed events would swamp the log; keep what tells the job's story.
  if (e.kind == K::kSwathHeader || e.kind == K::kSwathCommitted || e.kind == K::kSwathPrinting || e.kind == K::kFeed)
    return;
  events_.push_back(Event{clock_s_(), event_name(e.kind), e.swath, e.cue, e.fabric_pos_um, e.text});
}

void JobRecorder::fault_injected(const std::string& what) {
  faults_.push_back(what);
  events_.push_back(Event{clock_s_(), "fault_injected", 0, 0, controller_.fabric_pos_um(), what});
}

void JobRecorder::job_finished(const device::JobReportMsg& report) {
  if (report.outcome == device::JobOutcome::kLost && active_) {
    // The fabric stays in the printer: a resume of the job goes on printing on it.
    lost_ = true;
    ++losses_;
    return;
  }
  finish(report, std::string(device::to_string(report.outcome)));
}

void JobRecorder::close() {
  if (active_) finish(controller_.current_report(), lost_ ? "lost" : "incomplete", true);
  using nlohmann::json;
  json run;
  json edges = json::array();
  for (const auto& e : all_edges_)
    edges.push_back({{"line", e.line}, {"level", e.level ? 1 : 0}, {"time_s", e.time_s}, {"fabric_um", e.fabric_um}});
  run["gpio_edges"] = edges;
  run["usb"] = {{"out_urbs", usb_.out_urbs}, {"out_bytes", usb_.out_bytes}, {"in_urbs", usb_.in_urbs},
                {"in_bytes", usb_.in_bytes}, {"stalls", usb_.stalls},       {"stalled_urbs", usb_.stalled_urbs},
                {"halts_cleared", usb_.halts_cleared},
                {"soft_resets", usb_.soft_resets}, {"control_requests", usb_.control_requests}};
  json jobs = json::array();
  for (const auto& d : written_) jobs.push_back(d.string());
  run["jobs"] = jobs;
  run["duration_s"] = clock_s_();
  std::ofstream(options_.out_dir / "printsim.json") << run.dump(2) << "\n";
  std::unique_lock lock(writer_mu_);
  writer_cv_.wait(lock, [&] { return writer_queue_.empty(); });
}

void JobRecorder::finish(const device::JobReportMsg& report, const std::string& outcome, bool keep_journal) {
  if (!active_) return;
  active_ = false;
  // An open job's journal stays for a printsim that resumes it; an ended job's goes.
  if (journal_ && !keep_journal) journal_->discard();
  journal_.reset();
  using nlohmann::json;
  const auto& m = controller_.model();
  json j;
  json inks = json::array();
  for (const auto& ink : m.inks) inks.push_back(ink.name);
  j["printer"] = {{"model", m.name}, {"dpi_x", m.dpi_x}, {"dpi_y", m.dpi_y}, {"bits_per_pixel", m.bits_per_pixel},
                  {"inks", inks}};
  j["job"] = {{"id", report.job_id},
              {"name", job_.name},
              {"outcome", outcome},
              {"condition", std::string(device::to_string(report.condition))},
              {"first_swath", report.first_swath},
              {"resumes", resumes_},
              {"losses", losses_},
              {"unplugs", unplugs_},
              {"started_s", started_s_},
              {"finished_s", clock_s_()}};
  json drops = json::object();
  for (std::size_t i = 0; i < m.inks.size() && i < report.drops_per_ink.size(); ++i)
    drops[m.inks[i].name] = report.drops_per_ink[i];
  j["counters"] = {{"swaths_printed", report.swaths_printed},
                   {"drops_per_ink", drops},
                   {"feed_travel_um", report.feed_travel_um},
                   {"print_time_s", static_cast<double>(report.print_time_us) / 1e6},
                   {"cues_fired", report.cues_fired},
                   {"overruns", report.overruns},
                   {"row_mismatches", controller_.row_mismatches()},
                   {"head_row_offset_min", controller_.head_offset_min()},
                   {"head_row_offset_max", controller_.head_offset_max()}};
  const auto& rx = controller_.link();
  j["link"] = {{"frames_on_wire", rx.frames_on_wire()}, {"crc_errors", rx.crc_errors()},
               {"gaps", rx.gaps()},                     {"naks", rx.naks()},
               {"duplicates", rx.duplicates()},         {"injected_drops", rx.injected_drops()},
               {"injected_corruptions", rx.injected_corruptions()}};
  j["usb"] = {{"out_urbs", usb_.out_urbs}, {"out_bytes", usb_.out_bytes},
              {"in_urbs", usb_.in_urbs},   {"in_bytes", usb_.in_bytes},
              {"stalls", usb_.stalls},     {"stalled_urbs", usb_.stalled_urbs},
              {"halts_cleared", usb_.halts_cleared},
              {"soft_resets", usb_.soft_resets}, {"control_requests", usb_.control_requests}};
  json edges = json::array();
  for (const auto& e : edges_)
    edges.push_back({{"line", e.line}, {"level", e.level ? 1 : 0}, {"time_s", e.time_s}, {"fabric_um", e.fabric_um}});
  j["gpio_edges"] = edges;
  json events = json::array();
  for (const auto& e : events_)
    events.push_back({{"time_s", e.time_s}, {"kind", e.kind}, {"swath", e.swath}, {"cue", e.cue},
                      {"fabric_um", e.fabric_um}, {"text", e.text}});
  j["events"] = events;
  j["faults_injected"] = faults_;
  const std::filesystem::path dir = dir_;
  written_.push_back(dir);
  sim_log()->info("job {} '{}' {}: {} swaths printed, outputs in {}", report.job_id, job_.name, outcome,
                  report.swaths_printed, dir.string());
  std::shared_ptr<FabricCanvas> canvas(canvas_.release());
  write_async([this, j = std::move(j), dir, canvas]() mutable {
    std::string err;
    if (canvas) {
      auto s = canvas->finish(dir / "fabric.tif", dir / "fabric.png");
      if (s) {
        j["fabric"] = {{"width_px", s->width_px},           {"height_px", s->height_px},
                       {"channels", j["printer"]["inks"]},
                       {"preview_scale", s->preview_scale}, {"clipped_pixels", s->clipped_pixels},
                       {"late_rows", s->late_rows},         {"peak_window_rows", s->peak_window_rows}};
      } else {
        err = s.error().what();
      }
    }
    std::ofstream out(dir / "printer.json");
    out << j.dump(2) << "\n";
    if (!out && err.empty()) err = (dir / "printer.json").string() + ": cannot write";
    if (!err.empty()) {
      sim_log()->error("{}", err);
      std::lock_guard lock(writer_mu_);
      if (error_.empty()) error_ = err;
    }
  });
}

}  // namespace tp::sim
