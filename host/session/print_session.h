// host/session/print_session.h: the host's print session: opens the printer (USB through
// drivers/, plus the cutting table's GPIO lines), runs a job swath by swath within the printer's
// credits, fires cutter cues and notch marks when the printer reaches them, reports every
// printed swath (the pipeline's checkpoint), survives an unplug/replug or a host restart by asking
// the printer which job and swath it holds and resuming there, resumes a job the printer lost
// (power loss, buffer cleared) from its last printed swath with the fabric position continuous,
// and returns the printer's counters at the end.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device/protocol/host_link.h"
#include "device/protocol/messages.h"
#include "drivers/gpio/gpio_lines.h"
#include "drivers/usb/usb_transport.h"
#include "geometry/common/cancel.h"
#include "host/common/error.h"
#include "host/job/printer_choice.h"

namespace tp::host {

struct PrinterConfig {
  /// kSim: the printsim printer (the process must run under printsim, see sim_reexec.h);
  /// kUsb: a real printer. Both go through the same USB and GPIO drivers; kNone cannot be opened.
  PrinterChoice printer = PrinterChoice::kSim;
  drivers::UsbOptions usb;
  bool use_gpio = true;  ///< without GPIO, cues are acknowledged without firing a line
  drivers::GpioConfig gpio;
  std::chrono::milliseconds open_timeout{5000};
  /// How long an unplugged printer may stay away before the job fails (a printer re-enumerates in
  /// a second or two; one that stays away longer needs the operator). Every caller (printctl run,
  /// printd, link-job) gets this limit unless it sets another.
  std::chrono::milliseconds reconnect_timeout{5000};
  std::chrono::milliseconds cutter_ready_timeout{10000};
  std::chrono::microseconds cue_pulse{10000};          ///< width of the cue and notch pulses
  std::chrono::milliseconds max_pause{std::chrono::minutes(30)};  ///< longest printer pause tolerated
  std::chrono::milliseconds finish_timeout{std::chrono::minutes(10)};  ///< job end to printer idle
  std::optional<std::filesystem::path> wire_recording;  ///< record the link for `printctl wire-dump`
  device::LinkOptions link;
};

struct JobStart {
  std::uint64_t job_id = 0;
  std::string name;
  /// The host's checkpoint: swaths below this were printed in an earlier attempt (0: a fresh job).
  /// The printer's own record decides where the job resumes (see resume_swath()).
  std::uint32_t first_swath = 0;
  std::uint32_t fabric_width_px = 0;  ///< marker width at the printer's dpi_x (0: print width)
};

/// A cue as queued and, once fired, where the printer's fabric was.
struct CueRecord {
  std::uint32_t id = 0;
  device::CueKind kind = device::CueKind::kCut;
  std::int64_t position_um = 0;
  std::int32_t x_um = 0;
  bool fired = false;
  std::int64_t fired_at_um = 0;
};

struct SessionStats {
  std::uint32_t swaths_sent = 0;     ///< sent on the wire (resends after a reconnect included)
  std::uint32_t swaths_skipped = 0;  ///< handed in but already acknowledged (resume)
  std::uint32_t swaths_acked = 0;
  std::uint32_t swaths_resent = 0;   ///< sent again after a reconnect
  std::uint32_t reconnects = 0;
  double recovery_ms_last = 0;       ///< unplug noticed -> link back and job re-attached
  double recovery_ms_max = 0;
  std::uint64_t bytes_sent = 0;      ///< swath data bytes, first sends only
  double credit_wait_s = 0;          ///< time spent waiting for printer buffer space
  double pause_s = 0;                ///< time the printer spent paused (ink, cover, media)
  std::uint32_t lost_job_resumes = 0;  ///< times the printer lost the job and it resumed where it stopped
  bool reattached = false;           ///< begin_job found the job still open on the printer
  device::LinkStats link;
};

struct JobResult {
  device::JobReportMsg report;  ///< the printer's counters
  SessionStats stats;
  std::vector<CueRecord> cues;
};

class PrintSession {
 public:
  /// Opens the printer and the GPIO lines and checks the protocol version (kPrinter errors say
  /// which: not found, busy, incompatible).
  [[nodiscard]] static Result<std::unique_ptr<PrintSession>> open(const PrinterConfig& config);
  /// A session over an existing transport (tests: device::FirmwareTransport), without GPIO
  /// unless `gpio` is given.
  [[nodiscard]] static Result<std::unique_ptr<PrintSession>> open_with(
      std::unique_ptr<device::Transport> transport, const PrinterConfig& config,
      std::unique_ptr<drivers::GpioLines> gpio = nullptr);
  ~PrintSession();

  /// What the printer said it is at the handshake.
  [[nodiscard]] const device::IdentifyMsg& printer() const;
  /// Called with each swath index the printer acknowledges (received and checked), in order.
  void on_swath_acked(std::function<void(std::uint32_t index)> callback);
  /// Called when the printer reports swaths laid on the fabric: the highest printed index and the
  /// fabric position (um from the job's start) it was laid at. The pipeline's resume checkpoint.
  void on_swath_printed(std::function<void(std::uint32_t index, std::int64_t fabric_um)> callback);
  /// Called with each new status report the printer sends (state, faults, buffer, counters), as
  /// it arrives: the live view printd serves. Keep it quick.
  void on_status(std::function<void(const device::StatusMsg&)> callback) { on_status_ = std::move(callback); }
  /// Called once per cue when it fires on the cutting table (its GPIO line pulsed, or acknowledged
  /// without GPIO), with where the fabric stood.
  void on_cue_fired(std::function<void(const CueRecord&)> callback) { on_cue_fired_ = std::move(callback); }

  /// Opens a job on the printer, after asking it what it holds of this job: the same job still
  /// open (a host restart or reconnect) is re-attached and resumes after the swaths the printer
  /// received; a job it lost resumes from its last printed swath, with the feed to the right
  /// fabric position; a job it completed is not printed again (end_job() returns its report). A
  /// checkpoint the printer has no record of fails with an operator message (kPrinter).
  [[nodiscard]] Status begin_job(const JobStart& job);
  /// The first swath index the pipeline must hand in after begin_job() (lower ones are skipped).
  [[nodiscard]] std::uint32_t resume_swath() const { return next_send_; }
  /// True when begin_job() found the job already completed on the printer.
  [[nodiscard]] bool finished_on_printer() const { return finished_on_printer_; }
  /// Fabric position (um from the job's start) once every swath handed in so far is fed: the
  /// final feed is the marker's end minus this.
  [[nodiscard]] std::int64_t fabric_after_swaths_um() const { return planned_end_um_; }
  /// Sends one swath (indices consecutive from 0, or skipped if already acknowledged), blocking
  /// while the printer's buffer is full. Handles cues, pauses, faults, the emergency stop and
  /// reconnects meanwhile. Fails with kCancelled (the job is aborted on the printer) or kPrinter.
  [[nodiscard]] Status send_swath(const device::Swath& swath, const geometry::CancelToken& cancel);
  /// Queues a cutter cue or notch mark at `position_um` of fabric feed since the job began; it
  /// fires when the printer stops there (within one feed step).
  [[nodiscard]] Status queue_cue(device::CueKind kind, std::int64_t position_um, std::int32_t x_um = 0);
  /// Ends the job: the printer prints what it holds, feeds `final_feed_um`, and reports.
  [[nodiscard]] Result<JobResult> end_job(std::uint32_t final_feed_um, const geometry::CancelToken& cancel);
  /// Aborts the job on the printer (buffered swaths are discarded).
  [[nodiscard]] Status abort_job(const std::string& reason);

  [[nodiscard]] const SessionStats& stats() const { return stats_; }
  [[nodiscard]] const device::StatusMsg* printer_status() const { return link_->status(); }
  [[nodiscard]] std::string describe() const;

 private:
  PrintSession(PrinterConfig config, std::unique_ptr<device::Transport> transport,
               std::unique_ptr<drivers::GpioLines> gpio);
  [[nodiscard]] Status connect();
  [[nodiscard]] Status service(std::chrono::milliseconds wait, const geometry::CancelToken* cancel);
  [[nodiscard]] Status recover(const device::Error& cause);
  // print_session_resume.cpp: asking the printer what it holds and resuming from it.
  [[nodiscard]] Status attach_or_open(const device::StatusMsg& st);
  [[nodiscard]] Status open_on_printer(std::uint32_t first_swath, std::int64_t fabric_pos_um);
  [[nodiscard]] Status resume_lost_job(const device::StatusMsg& st, bool& disconnected);
  [[nodiscard]] Status resend_after_reconnect(const device::StatusMsg& st, bool& again);
  [[nodiscard]] device::Status send_wire_swath(const device::Swath& swath);
  void note_printed(const device::StatusMsg& st);
  [[nodiscard]] Status absorb_status();
  [[nodiscard]] Status fire_cue(std::uint32_t id, const geometry::CancelToken* cancel);
  [[nodiscard]] Status check_emergency_stop();
  [[nodiscard]] Status send_cues_up_to(std::int64_t position_um);
  [[nodiscard]] Status transmit(const device::Swath& swath);
  [[nodiscard]] Status fail_job(ErrorCode code, const std::string& message);
  std::string job_where() const;

  PrinterConfig config_;
  std::unique_ptr<device::Transport> transport_;
  std::unique_ptr<device::Transport> recorder_;
  std::unique_ptr<device::HostLink> link_;
  std::unique_ptr<drivers::GpioLines> gpio_;
  device::IdentifyMsg identity_;
  std::function<void(std::uint32_t)> on_acked_;
  std::function<void(std::uint32_t, std::int64_t)> on_printed_;
  std::function<void(const device::StatusMsg&)> on_status_;
  std::function<void(const CueRecord&)> on_cue_fired_;

  bool active_ = false;
  bool ending_ = false;
  JobStart job_;
  std::uint32_t acked_next_ = 0;
  std::uint32_t printed_next_ = 0;
  std::uint32_t swath_count_ = 0;      ///< one past the highest index handed in
  std::uint32_t next_send_ = 0;        ///< index the next swath handed in must have to be sent
  std::int64_t planned_end_um_ = 0;    ///< fabric position after the swaths handed in (as planned)
  std::uint32_t final_feed_um_ = 0;
  /// Sent, not yet printed: they hold printer credit, and are resent after a reconnect (those not
  /// acknowledged) or after the printer lost the job (all of them).
  std::deque<device::Swath> unprinted_;
  /// Re-attached to a job the printer kept: the swaths below `reattach_held_until_` it had received
  /// but not printed are in its buffer, and the host never had them (its RIP resumes after them).
  /// Until they are printed they hold `reattach_held_bytes_` of the buffer and one slot each.
  std::uint32_t reattach_held_until_ = 0;
  std::size_t reattach_held_bytes_ = 0;
  /// Feed correction for swath `feed_fix_swath_` on the wire: the printer lost the job with the
  /// fabric standing elsewhere than where that swath's planned feed starts.
  std::optional<std::uint32_t> feed_fix_swath_;
  std::int64_t feed_fix_um_ = 0;
  std::optional<std::int64_t> lost_at_um_;  ///< resumed after a loss: cues up to here were passed
  bool finished_on_printer_ = false;
  std::uint32_t reopen_seq_ = 0;  ///< link sequence of the job_begin that reopened a lost job
  std::vector<CueRecord> cues_;
  std::uint32_t cues_sent_ = 0;        ///< cues with id <= this are on the printer
  std::uint64_t seen_status_ = 0;
  std::optional<std::chrono::steady_clock::time_point> paused_since_;
  std::chrono::steady_clock::time_point last_estop_check_{};
  SessionStats stats_;
};

}  // namespace tp::host
