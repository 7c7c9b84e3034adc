// simulator/printsim/job_recorder.h: what printsim keeps per job: the virtual fabric, the GPIO
// edge log with fabric positions (the virtual cutter), events and faults, written at the end of
// each job as fabric.tif, fabric.png and printer.json in the job's output folder.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "device/firmware/controller.h"
#include "simulator/fabric/fabric_canvas.h"
#include "simulator/printsim/fabric_journal.h"

namespace tp::sim {

struct UsbCounters;

struct RecorderOptions {
  std::filesystem::path out_dir;
  bool job_dirs = false;  ///< each job in <out_dir>/<job id>-<job name>/ (daemon runs) instead of out_dir itself
  bool fabric = true;     ///< lay drops and write images (off for link benchmarks)
  /// Keep each open job's printed swaths in a journal beside its fabric, so a printsim that is
  /// killed (power loss) and started again goes on with the same fabric (printsim --state).
  bool persist = false;
};

class JobRecorder final : public device::PrintSink {
 public:
  /// `controller`, `usb` and `clock_s` (seconds since printsim started) outlive the recorder.
  JobRecorder(RecorderOptions options, const device::PrinterController& controller, const UsbCounters& usb,
              std::function<double()> clock_s);
  ~JobRecorder() override;

  void job_started(const device::JobBeginMsg& job, bool resumed) override;
  void swath_printed(const device::SwathHeader& header, std::span<const std::uint8_t> raw,
                     std::int64_t fabric_row) override;
  void job_finished(const device::JobReportMsg& report) override;

  /// Logs an output line edge at the printer's current fabric position.
  void gpio_edge(const std::string& line, bool level);
  void firmware_event(const device::FirmwareEvent& event);
  void fault_injected(const std::string& what);
  void note_unplug() { ++unplugs_; }
  /// printsim is ending: a job still open is written out as "incomplete", printsim.json (every
  /// GPIO edge of the run, USB counters, the jobs) goes to the output folder, and this waits
  /// until every job's files are written.
  void close();
  /// Folders of the jobs written so far.
  [[nodiscard]] const std::vector<std::filesystem::path>& written() const { return written_; }
  /// First error met writing outputs (empty if none; valid after close()).
  [[nodiscard]] std::string error() const;

 private:
  void finish(const device::JobReportMsg& report, const std::string& outcome, bool keep_journal = false);
  void start_journal(const device::JobBeginMsg& job);
  // Images are written on a worker thread: a long roll takes a while to compress, and the
  // printer must keep answering the host meanwhile.
  void write_async(std::function<void()> work);
  void writer_loop();
  std::filesystem::path job_dir(const device::JobBeginMsg& job) const;

  RecorderOptions options_;
  const device::PrinterController& controller_;
  const UsbCounters& usb_;
  std::function<double()> clock_s_;
  bool active_ = false;
  device::JobBeginMsg job_;
  std::filesystem::path dir_;
  std::unique_ptr<FabricCanvas> canvas_;
  double started_s_ = 0;
  int resumes_ = 0;
  int unplugs_ = 0;
  int losses_ = 0;      ///< times the printer lost this job (power loss, buffer cleared)
  bool lost_ = false;   ///< the printer lost the job; the fabric stays for its resume
  std::optional<FabricJournal> journal_;
  struct Edge {
    std::string line;
    bool level;
    double time_s;
    std::int64_t fabric_um;
  };
  struct Event {
    double time_s;
    std::string kind;
    std::uint32_t swath;
    std::uint32_t cue;
    std::int64_t fabric_um;
    std::string text;
  };
  std::vector<Edge> edges_;
  std::vector<Edge> all_edges_;  ///< the whole run's, for printsim.json
  std::vector<Event> events_;
  std::vector<std::string> faults_;
  std::vector<std::filesystem::path> written_;
  mutable std::mutex writer_mu_;
  std::condition_variable writer_cv_;
  std::deque<std::function<void()>> writer_queue_;
  bool writer_stop_ = false;
  std::string error_;
  std::thread writer_;
};

}  // namespace tp::sim
