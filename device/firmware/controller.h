// device/firmware/controller.h: the printer controller a real printer's firmware would run: the
// link receiver, the swath buffer with its credits, cutter cues, and the state machine
// (idle, job, printing, feeding, waiting for a cue, paused, fault, aborting) with the printer
// model's timing. The simulator runs it behind emulated USB; tests run it in-process.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "device/firmware/link_receiver.h"
#include "device/model/printer_model.h"
#include "device/protocol/messages.h"

namespace tp::device {

/// Where printed ink and fabric go (the simulator's virtual fabric).
class PrintSink {
 public:
  virtual ~PrintSink() = default;
  /// A job began, or (`resumed`) the host re-attached to the running job after a reconnect.
  virtual void job_started(const JobBeginMsg& job, bool resumed) = 0;
  /// A swath was printed. `raw` is its decompressed data (layout in swath.h); its row 0 landed
  /// on fabric row `fabric_row` (at dpi_y, from the job's start).
  virtual void swath_printed(const SwathHeader& header, std::span<const std::uint8_t> raw,
                             std::int64_t fabric_row) = 0;
  /// The job ended (completed, aborted or failed).
  virtual void job_finished(const JobReportMsg& report) = 0;
};

enum class FirmwareEventKind : std::uint8_t {
  kJobBegin,
  kSwathHeader,     ///< a swath's header was accepted; its data is arriving
  kSwathCommitted,  ///< a swath arrived complete and intact
  kSwathPrinting,   ///< a pass is about to start (faults injected here stop it unprinted)
  kSwathPrinted,
  kFeed,
  kCueReached,
  kStateChanged,
  kReject,
  kJobEnd,
};

struct FirmwareEvent {
  FirmwareEventKind kind = FirmwareEventKind::kStateChanged;
  std::uint32_t swath = 0;
  std::uint32_t cue = 0;
  std::int64_t fabric_pos_um = 0;
  PrinterState state = PrinterState::kIdle;
  std::string text;
};

using FirmwareObserver = std::function<void(const FirmwareEvent&)>;

/// What the controller keeps across a power loss (a real controller's non-volatile memory): the
/// last job, what of it is on the fabric and where the fabric stood. A job still open when the
/// power went is "lost" (JobOutcome::kLost); a job_begin for the same id resumes its counters.
struct NonVolatileState {
  std::uint64_t last_job_id = 0;
  JobOutcome last_outcome = JobOutcome::kNone;
  std::uint32_t last_printed_next = 0;
  std::int64_t last_printed_fabric_um = 0;
  std::int64_t last_fabric_pos_um = 0;
  std::optional<JobReportMsg> last_report;  ///< the last job's counters (for kLost: up to the loss)
};

struct FirmwareOptions {
  /// Modelled seconds per wall-clock second; 0 prints as fast as data arrives (print times are
  /// still modelled and reported).
  double speed = 0;
  std::string firmware_version = "tp-fw 1.0.0";
};

class PrinterController {
 public:
  PrinterController(PrinterModel model, PrintSink* sink, FirmwareOptions options = {});

  /// Bytes from the host (bulk OUT), at time `now_us`. Everything is consumed: the host keeps
  /// within the credits the status reports; a swath sent without credit is refused.
  void receive(std::span<const std::uint8_t> bytes, std::int64_t now_us);
  /// Bytes for the host (bulk IN): queued replies, then a status if anything changed; whole
  /// frames only, at most `max_bytes`. Empty when there is nothing to say.
  std::vector<std::uint8_t> transmit(std::size_t max_bytes);
  [[nodiscard]] bool has_output() const { return !out_.empty() || status_dirty_; }
  /// Runs the print engine up to `now_us`: completes passes and feeds that are due, starts the next.
  void advance(std::int64_t now_us);
  /// When advance() next has timed work to finish (INT64_MAX if none).
  [[nodiscard]] std::int64_t next_event_us() const;
  /// USB soft reset or a new connection: forget partial frames and the partly received swath.
  /// The job, committed swaths, cues and fabric position stay.
  void link_reset();
  /// Sets or clears a pausing condition (kInkLow, kCoverOpen, kMediaOut).
  void set_condition(PrinterCondition condition, bool active);
  /// Stops the job with a fault (kHeadStrike, kMediaJam, kEmergencyStop); the host must abort.
  void raise_fault(PrinterCondition condition);
  /// The operator cleared the printer (or it reset): the open job and its buffered swaths are
  /// dropped and the status reports the job as kLost, with what was printed and where the fabric
  /// stands. The fabric does not move.
  void lose_job(const std::string& why);
  /// What survives a power loss now (an open job counts as lost).
  [[nodiscard]] NonVolatileState nonvolatile() const;
  /// Power-on with what survived (before any link traffic): the controller starts idle.
  void restore(const NonVolatileState& state);
  void set_observer(FirmwareObserver observer) { observer_ = std::move(observer); }
  /// Where printed swaths go (may be set after construction; nullptr drops them).
  void set_sink(PrintSink* sink) { sink_ = sink; }
  void set_rx_fault_hook(RxFaultHook hook) { rx_.set_fault_hook(std::move(hook)); }

  [[nodiscard]] StatusMsg status() const;
  [[nodiscard]] IdentifyMsg identify() const;
  [[nodiscard]] PrinterState state() const;
  [[nodiscard]] const PrinterModel& model() const { return model_; }
  [[nodiscard]] const LinkReceiver& link() const { return rx_; }
  [[nodiscard]] std::int64_t fabric_pos_um() const { return fabric_pos_um_; }
  [[nodiscard]] bool job_active() const { return job_active_; }
  /// Swaths whose first row lay outside the head's reach as the feeds placed it (the spread of
  /// first_row minus head row exceeded the nozzle span): feeds and rows disagree.
  [[nodiscard]] std::uint32_t row_mismatches() const { return row_mismatches_; }
  /// The counters of the open job so far (outcome kNone), as a job report.
  [[nodiscard]] JobReportMsg current_report() const { return report(); }
  /// Range of (swath first_row - head row from the feeds) over the job, in rows.
  [[nodiscard]] std::int64_t head_offset_min() const { return head_offset_min_; }
  [[nodiscard]] std::int64_t head_offset_max() const { return head_offset_max_; }

 private:
  struct BufferedSwath {
    SwathHeaderMsg msg;
    std::vector<std::uint8_t> data;
    bool fed = false;
    bool feed_only = false;  ///< a bare kFeed kept in order among the swaths
  };
  struct Cue {
    CutterCueMsg msg;
    bool reached = false;
  };
  enum class OpKind : std::uint8_t { kNone, kFeed, kPrint, kFinalFeed };

  // controller.cpp: link and message handling.
  void handle(const Frame& frame);
  void on_hello(const Frame& frame);
  void on_job_begin(const JobBeginMsg& m);
  void on_swath_header(const SwathHeaderMsg& m, std::uint32_t seq);
  void on_swath_data(const SwathDataMsg& m, std::uint32_t seq);
  void on_abort(const std::string& reason);
  void reject(MessageType type, std::uint32_t seq, ErrorCode code, std::string message);
  void queue_frame(MessageType type, const std::vector<std::uint8_t>& payload);
  void emit(FirmwareEventKind kind, std::uint32_t swath = 0, std::uint32_t cue = 0, std::string text = {});
  void note_state();
  std::uint64_t buffered_bytes() const;
  std::size_t buffered_slots() const;

  // controller_engine.cpp: the print engine.
  void start_op(OpKind kind, double modelled_s, std::int64_t now_us);
  void complete_op();
  void print_front();
  void check_cues();
  /// Ends the open job with `outcome`: records it as the last job, clears the buffer and cues,
  /// and (with `send_report`) queues its report to the host.
  void finish_job(JobOutcome outcome, bool send_report = true);
  JobReportMsg report() const;

  PrinterModel model_;
  PrintSink* sink_;
  FirmwareOptions options_;
  FirmwareObserver observer_;
  LinkReceiver rx_;
  std::deque<std::vector<std::uint8_t>> out_;
  bool status_dirty_ = true;
  std::uint32_t tx_seq_ = 1;
  std::uint16_t negotiated_version_ = 0;
  PrinterState last_state_ = PrinterState::kIdle;

  // The job.
  bool job_active_ = false;
  JobBeginMsg job_;
  std::uint32_t swath_next_ = 0;
  std::uint32_t printed_next_ = 0;
  bool end_requested_ = false;
  JobEndMsg end_;
  bool final_feed_done_ = false;
  std::int64_t fabric_pos_um_ = 0;
  std::int64_t feed_travel_um_ = 0;
  double print_time_s_ = 0;
  std::vector<std::uint64_t> drops_per_ink_;
  std::uint32_t swaths_printed_ = 0;
  std::uint32_t cues_fired_ = 0;
  std::uint32_t overruns_ = 0;
  std::uint32_t row_mismatches_ = 0;
  std::int64_t head_offset_min_ = 0;
  std::int64_t head_offset_max_ = 0;
  std::int64_t printed_fabric_um_ = 0;  ///< where the fabric stood when the last swath was laid
  std::int64_t queued_fabric_um_ = 0;   ///< fabric_pos_um_ plus the feeds of committed swaths not yet fed
  std::uint32_t report_first_swath_ = 0;  ///< first swath of the job, kept across a resume after loss

  // Swath reception and buffer.
  std::optional<BufferedSwath> rx_swath_;
  std::optional<std::uint32_t> ignoring_swath_;  ///< data of a refused or duplicate swath
  std::deque<BufferedSwath> buffer_;
  std::vector<std::uint8_t> raw_;  ///< decompression scratch, reused across swaths
  std::array<std::uint8_t, 256> drop_table_{};  ///< drops per byte of packed pixels

  // Cues, conditions, engine.
  std::map<std::uint32_t, Cue> cues_;
  std::uint32_t cue_waiting_ = 0;
  std::uint32_t pause_mask_ = 0;
  PrinterCondition fault_ = PrinterCondition::kNone;
  OpKind op_ = OpKind::kNone;
  std::int64_t op_end_us_ = 0;
  std::int64_t op_feed_um_ = 0;
  double op_time_s_ = 0;
  std::int64_t now_us_ = 0;

  std::uint64_t last_job_id_ = 0;
  JobOutcome last_outcome_ = JobOutcome::kNone;
  std::uint32_t last_printed_next_ = 0;
  std::int64_t last_printed_fabric_um_ = 0;
  std::int64_t last_fabric_pos_um_ = 0;
  std::optional<JobReportMsg> last_report_;
};

}  // namespace tp::device
