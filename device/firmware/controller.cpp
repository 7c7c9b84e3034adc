// device/firmware/controller.cpp: the controller's link side: hello, job and swath messages,
// credits, cues, pause/resume/abort, replies and status reports.
#include "device/firmware/controller.h"

#include <algorithm>
#include <cmath>

#include "device/protocol/crc.h"
#include "device/swath/packbits.h"

namespace tp::device {

std::array<std::uint8_t, 256> drop_count_table(int bpp);  // controller_engine.cpp

namespace {
// The largest PackBits stream of a swath: every channel row encoded on its own (as the RIP does)
// at the codec's worst case, which also bounds the swath encoded in one piece.
std::uint64_t packbits_bound(const SwathHeader& h) {
  return std::uint64_t(h.rows) * h.channels * packbits_max_size(swath_row_bytes(h));
}
// Cue table bound: a marker has a few cues per piece; this caps a hostile host's memory use.
constexpr std::size_t kMaxCues = 4096;
}  // namespace

PrinterController::PrinterController(PrinterModel model, PrintSink* sink, FirmwareOptions options)
    : model_(std::move(model)), sink_(sink), options_(std::move(options)) {
  drops_per_ink_.assign(model_.inks.size(), 0);
  drop_table_ = drop_count_table(model_.bits_per_pixel);
}

void PrinterController::emit(FirmwareEventKind kind, std::uint32_t swath, std::uint32_t cue, std::string text) {
  if (!observer_) return;
  FirmwareEvent e;
  e.kind = kind;
  e.swath = swath;
  e.cue = cue;
  e.fabric_pos_um = fabric_pos_um_;
  e.state = state();
  e.text = std::move(text);
  observer_(e);
}

void PrinterController::note_state() {
  const PrinterState s = state();
  if (s != last_state_) {
    last_state_ = s;
    status_dirty_ = true;
    emit(FirmwareEventKind::kStateChanged, 0, 0, std::string(to_string(s)));
  }
}

PrinterState PrinterController::state() const {
  if (!job_active_) return PrinterState::kIdle;
  if (fault_ != PrinterCondition::kNone) return PrinterState::kFault;
  if (op_ == OpKind::kPrint) return PrinterState::kPrinting;
  if (op_ == OpKind::kFeed || op_ == OpKind::kFinalFeed) return PrinterState::kFeeding;
  if (cue_waiting_ != 0) return PrinterState::kWaitingForCue;
  if (pause_mask_ != 0) return PrinterState::kPaused;
  return PrinterState::kJob;
}

std::uint64_t PrinterController::buffered_bytes() const {
  std::uint64_t n = rx_swath_ ? rx_swath_->msg.data_bytes : 0;
  for (const auto& s : buffer_) n += s.msg.data_bytes;
  return n;
}

std::size_t PrinterController::buffered_slots() const {
  std::size_t n = rx_swath_ ? 1 : 0;
  for (const auto& s : buffer_) n += s.feed_only ? 0 : 1;
  return n;
}

StatusMsg PrinterController::status() const {
  StatusMsg s;
  s.ack_seq = rx_.ack_seq();
  s.naks = rx_.naks();
  s.state = state();
  if (fault_ != PrinterCondition::kNone) {
    s.condition = fault_;
  } else {
    // Report the lowest active pause reason.
    for (std::uint16_t c = 1; c < 16; ++c)
      if (pause_mask_ & (1u << c)) {
        s.condition = static_cast<PrinterCondition>(c);
        break;
      }
  }
  s.job_id = job_active_ ? job_.job_id : 0;
  s.swath_next = swath_next_;
  s.printed_next = printed_next_;
  const std::size_t used = buffered_slots();
  s.free_slots = static_cast<std::uint16_t>(used >= model_.swath_buffer_slots ? 0 : model_.swath_buffer_slots - used);
  const std::uint64_t bytes = buffered_bytes();
  s.free_bytes = static_cast<std::uint32_t>(bytes >= model_.swath_buffer_bytes ? 0 : model_.swath_buffer_bytes - bytes);
  s.fabric_pos_um = fabric_pos_um_;
  s.cue_waiting = cue_waiting_;
  s.cues_registered = cues_.empty() ? 0 : cues_.rbegin()->first;
  s.last_job_id = last_job_id_;
  s.last_outcome = last_outcome_;
  s.rx_crc_errors = rx_.crc_errors();
  s.rx_gaps = rx_.gaps();
  s.printed_fabric_um = job_active_ ? printed_fabric_um_ : 0;
  s.queued_fabric_um = job_active_ ? queued_fabric_um_ : 0;
  s.last_printed_next = last_printed_next_;
  s.last_printed_fabric_um = last_printed_fabric_um_;
  s.last_fabric_pos_um = last_fabric_pos_um_;
  return s;
}

IdentifyMsg PrinterController::identify() const {
  IdentifyMsg m;
  m.protocol_version = negotiated_version_;
  m.min_version = model_.protocol_version;
  m.max_version = model_.protocol_version;
  m.model = model_.name;
  m.ieee1284_id = model_.ieee1284_id;
  m.firmware = options_.firmware_version;
  m.max_payload_bytes = kMaxFramePayloadBytes;
  m.dpi_x = model_.dpi_x;
  m.dpi_y = model_.dpi_y;
  m.nozzles_per_ink = static_cast<std::uint16_t>(model_.nozzles_per_ink);
  m.bits_per_pixel = static_cast<std::uint8_t>(model_.bits_per_pixel);
  for (const auto& ink : model_.inks) m.inks.push_back(ink.name);
  m.swath_slots = model_.swath_buffer_slots;
  m.swath_buffer_bytes = model_.swath_buffer_bytes;
  m.print_width_um = static_cast<std::uint32_t>(std::lround(model_.print_width_mm * 1000));
  return m;
}

void PrinterController::queue_frame(MessageType type, const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> frame;
  if (encode_frame(type, tx_seq_++, payload, frame)) out_.push_back(std::move(frame));
}

void PrinterController::reject(MessageType type, std::uint32_t seq, ErrorCode code, std::string message) {
  RejectMsg r;
  r.refused = type;
  r.seq = seq;
  r.code = code;
  r.message = std::move(message);
  emit(FirmwareEventKind::kReject, 0, 0, r.message);
  std::vector<std::uint8_t> payload;
  encode(r, payload);
  queue_frame(MessageType::kReject, payload);
}

std::vector<std::uint8_t> PrinterController::transmit(std::size_t max_bytes) {
  std::vector<std::uint8_t> bytes;
  while (!out_.empty() && bytes.size() + out_.front().size() <= max_bytes) {
    bytes.insert(bytes.end(), out_.front().begin(), out_.front().end());
    out_.pop_front();
  }
  if (status_dirty_ && out_.empty()) {
    std::vector<std::uint8_t> payload, frame;
    encode(status(), payload);
    if (encode_frame(MessageType::kStatus, tx_seq_, payload, frame) && bytes.size() + frame.size() <= max_bytes) {
      ++tx_seq_;
      bytes.insert(bytes.end(), frame.begin(), frame.end());
      status_dirty_ = false;
    }
  }
  return bytes;
}

void PrinterController::link_reset() {
  rx_.reset();
  out_.clear();
  // A partly received swath cannot be completed on a new connection: free its slot.
  rx_swath_.reset();
  ignoring_swath_.reset();
  status_dirty_ = true;
}

void PrinterController::receive(std::span<const std::uint8_t> bytes, std::int64_t now_us) {
  now_us_ = std::max(now_us_, now_us);
  rx_.feed(bytes);
  while (auto f = rx_.next()) handle(*f);
  // Every batch gets a report: acknowledgements, NAKs and credits travel in it.
  status_dirty_ = true;
  advance(now_us_);
}

void PrinterController::on_hello(const Frame& frame) {
  auto m = decode_hello(frame.payload);
  // A new link: replies queued for the old one are stale.
  out_.clear();
  rx_swath_.reset();
  ignoring_swath_.reset();
  const std::uint16_t mine = model_.protocol_version;
  negotiated_version_ = (m && m->min_version <= mine && mine <= m->max_version) ? mine : 0;
  std::vector<std::uint8_t> payload;
  encode(identify(), payload);
  queue_frame(MessageType::kIdentify, payload);
}

void PrinterController::handle(const Frame& frame) {
  const std::uint32_t seq = frame.header.seq;
  const MessageType type = frame.header.type;
  auto refuse_malformed = [&](const Error& e) { reject(type, seq, e.code, e.message); };
  if (type == MessageType::kHello) return on_hello(frame);
  if (negotiated_version_ == 0) {
    reject(type, seq, ErrorCode::kIncompatiblePrinter, "no protocol version agreed; send hello first");
    return;
  }
  switch (type) {
    case MessageType::kStatusQuery: status_dirty_ = true; break;
    case MessageType::kReportQuery:
      if (last_report_) {
        std::vector<std::uint8_t> payload;
        encode(*last_report_, payload);
        queue_frame(MessageType::kJobReport, payload);
      } else {
        reject(type, seq, ErrorCode::kBadState, "no job has finished yet");
      }
      break;
    case MessageType::kJobBegin: {
      auto m = decode_job_begin(frame.payload);
      if (!m) return refuse_malformed(m.error());
      on_job_begin(*m);
      break;
    }
    case MessageType::kJobEnd: {
      auto m = decode_job_end(frame.payload);
      if (!m) return refuse_malformed(m.error());
      if (!job_active_) return reject(type, seq, ErrorCode::kBadState, "job_end: no job open");
      end_requested_ = true;
      end_ = *m;
      break;
    }
    case MessageType::kSwathHeader: {
      auto m = decode_swath_header(frame.payload);
      if (!m) return refuse_malformed(m.error());
      on_swath_header(*m, seq);
      break;
    }
    case MessageType::kSwathData: {
      auto m = decode_swath_data(frame.payload);
      if (!m) return refuse_malformed(m.error());
      on_swath_data(*m, seq);
      break;
    }
    case MessageType::kFeed: {
      auto m = decode_feed(frame.payload);
      if (!m) return refuse_malformed(m.error());
      if (!job_active_) return reject(type, seq, ErrorCode::kBadState, "feed: no job open");
      // A bare feed travels as an empty swath entry so it keeps its place among the swaths.
      BufferedSwath feed;
      feed.feed_only = true;
      feed.msg.header.feed_before_um = m->feed_um;
      queued_fabric_um_ += m->feed_um;
      buffer_.push_back(std::move(feed));
      break;
    }
    case MessageType::kCutterCue: {
      auto m = decode_cutter_cue(frame.payload);
      if (!m) return refuse_malformed(m.error());
      if (!job_active_) return reject(type, seq, ErrorCode::kBadState, "cutter_cue: no job open");
      if (cues_.count(m->cue_id)) break;  // resent after a reconnect: already registered
      if (cues_.size() >= kMaxCues)
        return reject(type, seq, ErrorCode::kBufferFull, "cutter_cue " + std::to_string(m->cue_id) + ": cue table full");
      cues_[m->cue_id] = Cue{*m, false};
      check_cues();
      break;
    }
    case MessageType::kCueDone: {
      auto m = decode_cue_done(frame.payload);
      if (!m) return refuse_malformed(m.error());
      if (cue_waiting_ == m->cue_id) {
        cue_waiting_ = 0;
        ++cues_fired_;
        check_cues();
      }
      break;
    }
    case MessageType::kPause: set_condition(PrinterCondition::kHostPause, true); break;
    case MessageType::kResume: set_condition(PrinterCondition::kHostPause, false); break;
    case MessageType::kAbort: {
      auto m = decode_abort(frame.payload);
      if (!m) return refuse_malformed(m.error());
      on_abort(m->reason);
      break;
    }
    default:
      reject(type, seq, ErrorCode::kUnsupported, std::string(to_string(type)) + " is not a host message");
      break;
  }
  note_state();
}

void PrinterController::on_job_begin(const JobBeginMsg& m) {
  if (job_active_) {
    if (m.job_id == job_.job_id) {
      // The host re-attached after a reconnect: keep going where the printer is.
      if (sink_) sink_->job_started(m, true);
      emit(FirmwareEventKind::kJobBegin, swath_next_, 0, "resumed");
      return;
    }
    return reject(MessageType::kJobBegin, 0, ErrorCode::kBadState,
                  "job " + std::to_string(job_.job_id) + " ('" + job_.name + "') is still open; abort it first");
  }
  job_active_ = true;
  job_ = m;
  swath_next_ = printed_next_ = m.first_swath;
  end_requested_ = false;
  final_feed_done_ = false;
  fabric_pos_um_ = printed_fabric_um_ = queued_fabric_um_ = m.fabric_pos_um;
  feed_travel_um_ = 0;
  print_time_s_ = 0;
  drops_per_ink_.assign(model_.inks.size(), 0);
  swaths_printed_ = cues_fired_ = overruns_ = row_mismatches_ = 0;
  head_offset_min_ = head_offset_max_ = 0;
  report_first_swath_ = m.first_swath;
  // The host resumes a job this printer lost: its counters go on from where they stopped.
  const bool resumes_lost = last_outcome_ == JobOutcome::kLost && m.job_id == last_job_id_ && last_report_ &&
                            m.first_swath == last_printed_next_;
  if (resumes_lost) {
    const JobReportMsg& r = *last_report_;
    if (r.drops_per_ink.size() == drops_per_ink_.size()) drops_per_ink_ = r.drops_per_ink;
    swaths_printed_ = r.swaths_printed;
    feed_travel_um_ = r.feed_travel_um;
    print_time_s_ = static_cast<double>(r.print_time_us) / 1e6;
    cues_fired_ = r.cues_fired;
    report_first_swath_ = r.first_swath;
    // The last swath on the fabric is still the lost job's: the next feed starts from it.
    printed_fabric_um_ = last_printed_fabric_um_;
  }
  buffer_.clear();
  rx_swath_.reset();
  ignoring_swath_.reset();
  cues_.clear();
  cue_waiting_ = 0;
  fault_ = PrinterCondition::kNone;
  pause_mask_ &= ~(1u << static_cast<unsigned>(PrinterCondition::kHostPause));
  if (sink_) sink_->job_started(m, false);
  emit(FirmwareEventKind::kJobBegin, m.first_swath, 0, resumes_lost ? m.name + " (resumed after loss)" : m.name);
}

void PrinterController::on_swath_header(const SwathHeaderMsg& m, std::uint32_t seq) {
  const SwathHeader& h = m.header;
  const std::string what = "swath " + std::to_string(h.index);
  if (!job_active_) return reject(MessageType::kSwathHeader, seq, ErrorCode::kBadState, what + ": no job open");
  if (h.index < swath_next_) {
    ignoring_swath_ = h.index;  // already committed before a reconnect: drop its data quietly
    return;
  }
  auto refuse = [&](ErrorCode code, const std::string& why) {
    ignoring_swath_ = h.index;
    reject(MessageType::kSwathHeader, seq, code, what + ": " + why);
  };
  if (h.index != swath_next_) return refuse(ErrorCode::kSequenceError, "expected swath " + std::to_string(swath_next_));
  if (h.channels != model_.inks.size())
    return refuse(ErrorCode::kInvalidArgument, std::to_string(h.channels) + " channels, printer has " +
                                                   std::to_string(model_.inks.size()) + " inks");
  if (h.bits_per_pixel != model_.bits_per_pixel)
    return refuse(ErrorCode::kInvalidArgument, std::to_string(h.bits_per_pixel) + " bits per pixel, printer takes " +
                                                   std::to_string(model_.bits_per_pixel));
  if (h.rows > static_cast<std::uint32_t>(model_.nozzles_per_ink) || h.row_step == 0)
    return refuse(ErrorCode::kInvalidArgument, std::to_string(h.rows) + " rows with row step " +
                                                   std::to_string(h.row_step) + " (head has " +
                                                   std::to_string(model_.nozzles_per_ink) + " nozzles per ink)");
  const double width_limit_px = model_.print_width_mm * model_.dpi_x / 25.4 + 1;
  if (h.x_start_px < 0 || h.width_px == 0 || h.x_start_px + static_cast<double>(h.width_px) > width_limit_px)
    return refuse(ErrorCode::kInvalidArgument, "columns " + std::to_string(h.x_start_px) + "+" +
                                                   std::to_string(h.width_px) + " outside the print width");
  if (h.raw_bytes != swath_raw_bytes(h))
    return refuse(ErrorCode::kInvalidArgument, "raw_bytes " + std::to_string(h.raw_bytes) + " but geometry needs " +
                                                   std::to_string(swath_raw_bytes(h)));
  const bool size_ok =
      h.compression == SwathCompression::kNone ? m.data_bytes == h.raw_bytes : m.data_bytes <= packbits_bound(h);
  if (!size_ok) return refuse(ErrorCode::kInvalidArgument, "data_bytes " + std::to_string(m.data_bytes) + " impossible for its compression");
  // Credits: the host may not send more than the buffer holds.
  rx_swath_.reset();
  if (buffered_slots() + 1 > model_.swath_buffer_slots || buffered_bytes() + m.data_bytes > model_.swath_buffer_bytes) {
    ++overruns_;
    return refuse(ErrorCode::kBufferFull, "sent without credit (buffer holds " + std::to_string(buffered_slots()) +
                                              " swaths, " + std::to_string(buffered_bytes()) + " bytes)");
  }
  ignoring_swath_.reset();
  rx_swath_ = BufferedSwath{m, {}, false};
  rx_swath_->data.reserve(m.data_bytes);
  emit(FirmwareEventKind::kSwathHeader, h.index);
}

void PrinterController::on_swath_data(const SwathDataMsg& m, std::uint32_t seq) {
  if (ignoring_swath_ && *ignoring_swath_ == m.swath_index) return;
  const std::string what = "swath " + std::to_string(m.swath_index);
  if (!rx_swath_ || rx_swath_->msg.header.index != m.swath_index)
    return reject(MessageType::kSwathData, seq, ErrorCode::kSequenceError, what + ": data without its header");
  auto& rx = *rx_swath_;
  if (m.offset != rx.data.size() || rx.data.size() + m.data.size() > rx.msg.data_bytes) {
    rx_swath_.reset();
    return reject(MessageType::kSwathData, seq, ErrorCode::kSequenceError,
                  what + ": chunk at offset " + std::to_string(m.offset) + " does not follow byte " +
                      std::to_string(rx.data.size()) + " of " + std::to_string(rx.msg.data_bytes));
  }
  rx.data.insert(rx.data.end(), m.data.begin(), m.data.end());
  if (rx.data.size() < rx.msg.data_bytes) return;
  if (crc32(rx.data) != rx.msg.data_crc32) {
    rx_swath_.reset();
    return reject(MessageType::kSwathData, seq, ErrorCode::kCrcMismatch, what + ": data CRC mismatch; resend the swath");
  }
  queued_fabric_um_ += rx.msg.header.feed_before_um;
  buffer_.push_back(std::move(rx));
  rx_swath_.reset();
  ++swath_next_;
  emit(FirmwareEventKind::kSwathCommitted, m.swath_index);
}

void PrinterController::on_abort(const std::string& reason) {
  if (!job_active_) return;
  buffer_.clear();
  rx_swath_.reset();
  op_ = OpKind::kNone;
  emit(FirmwareEventKind::kJobEnd, printed_next_, 0, "aborted: " + reason);
  finish_job(fault_ != PrinterCondition::kNone ? JobOutcome::kFailed : JobOutcome::kAborted);
}

void PrinterController::set_condition(PrinterCondition condition, bool active) {
  const std::uint32_t bit = 1u << static_cast<unsigned>(condition);
  pause_mask_ = active ? (pause_mask_ | bit) : (pause_mask_ & ~bit);
  status_dirty_ = true;
  note_state();
}

void PrinterController::lose_job(const std::string& why) {
  if (!job_active_) return;
  emit(FirmwareEventKind::kJobEnd, printed_next_, 0, "lost: " + why);
  // No report goes to the host: the job is lost, and the host learns it from the status.
  finish_job(JobOutcome::kLost, /*send_report=*/false);
}

NonVolatileState PrinterController::nonvolatile() const {
  NonVolatileState nv;
  if (job_active_) {
    nv.last_job_id = job_.job_id;
    nv.last_outcome = JobOutcome::kLost;
    nv.last_printed_next = printed_next_;
    nv.last_printed_fabric_um = printed_fabric_um_;
    nv.last_fabric_pos_um = fabric_pos_um_;
    JobReportMsg r = report();
    r.outcome = JobOutcome::kLost;
    nv.last_report = r;
    return nv;
  }
  nv.last_job_id = last_job_id_;
  nv.last_outcome = last_outcome_;
  nv.last_printed_next = last_printed_next_;
  nv.last_printed_fabric_um = last_printed_fabric_um_;
  nv.last_fabric_pos_um = last_fabric_pos_um_;
  nv.last_report = last_report_;
  return nv;
}

void PrinterController::restore(const NonVolatileState& nv) {
  job_active_ = false;
  last_job_id_ = nv.last_job_id;
  last_outcome_ = nv.last_outcome;
  last_printed_next_ = nv.last_printed_next;
  last_printed_fabric_um_ = nv.last_printed_fabric_um;
  last_fabric_pos_um_ = nv.last_fabric_pos_um;
  last_report_ = nv.last_report;
  status_dirty_ = true;
}

void PrinterController::raise_fault(PrinterCondition condition) {
  if (!job_active_ || fault_ != PrinterCondition::kNone) return;
  fault_ = condition;
  // The pass or feed in progress stops where it is: it does not count as printed.
  op_ = OpKind::kNone;
  status_dirty_ = true;
  note_state();
}

}  // namespace tp::device
