// device/protocol/messages.cpp: payload encoders and validating decoders of every message.
#include "device/protocol/messages.h"

#include <string>

#include "device/protocol/internal/byte_io.h"

namespace tp::device {

using wire::ByteReader;
using wire::ByteWriter;

namespace {

// Upper bounds that keep a corrupt or hostile payload from asking for absurd allocations.
constexpr std::size_t kMaxInks = 16;

std::unexpected<Error> malformed(const char* msg, const std::string& what) {
  return fail(ErrorCode::kMalformedFrame, std::string(msg) + ": " + what);
}

// Ends a decode: a truncated field or trailing bytes make the payload malformed.
Status finish(const ByteReader& r, const char* msg) {
  if (!r.ok()) return malformed(msg, std::string("field '") + r.failed_field() + "' truncated");
  if (r.remaining() != 0)
    return malformed(msg, std::to_string(r.remaining()) + " unexpected trailing bytes");
  return {};
}

bool valid_state(std::uint8_t v) { return v <= static_cast<std::uint8_t>(PrinterState::kAborting); }
bool valid_condition(std::uint16_t v) {
  return to_string(static_cast<PrinterCondition>(v)) != "unknown";
}
bool valid_outcome(std::uint8_t v) { return v <= static_cast<std::uint8_t>(JobOutcome::kLost); }

}  // namespace

void encode(const HelloMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u16(m.min_version);
  w.u16(m.max_version);
  w.u32(m.max_payload_bytes);
  w.str(m.host);
}

Result<HelloMsg> decode_hello(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  HelloMsg m;
  m.min_version = r.u16("min_version");
  m.max_version = r.u16("max_version");
  m.max_payload_bytes = r.u32("max_payload_bytes");
  m.host = r.str("host");
  if (auto s = finish(r, "hello"); !s) return fail(s.error());
  if (m.min_version > m.max_version)
    return malformed("hello", "min_version " + std::to_string(m.min_version) + " above max_version " +
                                  std::to_string(m.max_version));
  return m;
}

void encode(const IdentifyMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u16(m.protocol_version);
  w.u16(m.min_version);
  w.u16(m.max_version);
  w.str(m.model);
  w.str(m.ieee1284_id);
  w.str(m.firmware);
  w.u32(m.max_payload_bytes);
  w.i32(m.dpi_x);
  w.i32(m.dpi_y);
  w.u16(m.nozzles_per_ink);
  w.u8(m.bits_per_pixel);
  w.u8(static_cast<std::uint8_t>(m.inks.size()));
  for (const auto& ink : m.inks) w.str(ink);
  w.u16(m.swath_slots);
  w.u32(m.swath_buffer_bytes);
  w.u32(m.print_width_um);
}

Result<IdentifyMsg> decode_identify(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  IdentifyMsg m;
  m.protocol_version = r.u16("protocol_version");
  m.min_version = r.u16("min_version");
  m.max_version = r.u16("max_version");
  m.model = r.str("model");
  m.ieee1284_id = r.str("ieee1284_id");
  m.firmware = r.str("firmware");
  m.max_payload_bytes = r.u32("max_payload_bytes");
  m.dpi_x = r.i32("dpi_x");
  m.dpi_y = r.i32("dpi_y");
  m.nozzles_per_ink = r.u16("nozzles_per_ink");
  m.bits_per_pixel = r.u8("bits_per_pixel");
  const std::size_t n_inks = r.u8("ink_count");
  if (n_inks > kMaxInks) return malformed("identify", std::to_string(n_inks) + " inks (limit 16)");
  for (std::size_t i = 0; i < n_inks && r.ok(); ++i) m.inks.push_back(r.str("ink_name"));
  m.swath_slots = r.u16("swath_slots");
  m.swath_buffer_bytes = r.u32("swath_buffer_bytes");
  m.print_width_um = r.u32("print_width_um");
  if (auto s = finish(r, "identify"); !s) return fail(s.error());
  return m;
}

void encode(const JobBeginMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u64(m.job_id);
  w.str(m.name);
  w.u32(m.first_swath);
  w.u32(m.fabric_width_px);
  w.i64(m.fabric_pos_um);
}

Result<JobBeginMsg> decode_job_begin(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  JobBeginMsg m;
  m.job_id = r.u64("job_id");
  m.name = r.str("name");
  m.first_swath = r.u32("first_swath");
  m.fabric_width_px = r.u32("fabric_width_px");
  m.fabric_pos_um = r.i64("fabric_pos_um");
  if (auto s = finish(r, "job_begin"); !s) return fail(s.error());
  return m;
}

void encode(const JobEndMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u32(m.swath_count);
  w.u32(m.final_feed_um);
}

Result<JobEndMsg> decode_job_end(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  JobEndMsg m;
  m.swath_count = r.u32("swath_count");
  m.final_feed_um = r.u32("final_feed_um");
  if (auto s = finish(r, "job_end"); !s) return fail(s.error());
  return m;
}

void encode(const SwathHeaderMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  const SwathHeader& h = m.header;
  w.u32(h.index);
  w.u16(h.pass);
  w.u8(static_cast<std::uint8_t>(h.direction));
  w.i64(h.first_row);
  w.u16(h.row_step);
  w.u32(h.rows);
  w.i32(h.x_start_px);
  w.u32(h.width_px);
  w.u8(h.channels);
  w.u8(h.bits_per_pixel);
  w.u32(h.feed_before_um);
  w.u8(static_cast<std::uint8_t>(h.compression));
  w.u32(h.raw_bytes);
  w.u32(m.data_bytes);
  w.u32(m.data_crc32);
}

Result<SwathHeaderMsg> decode_swath_header(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  SwathHeaderMsg m;
  SwathHeader& h = m.header;
  h.index = r.u32("index");
  h.pass = r.u16("pass");
  const std::uint8_t dir = r.u8("direction");
  h.first_row = r.i64("first_row");
  h.row_step = r.u16("row_step");
  h.rows = r.u32("rows");
  h.x_start_px = r.i32("x_start_px");
  h.width_px = r.u32("width_px");
  h.channels = r.u8("channels");
  h.bits_per_pixel = r.u8("bits_per_pixel");
  h.feed_before_um = r.u32("feed_before_um");
  const std::uint8_t comp = r.u8("compression");
  h.raw_bytes = r.u32("raw_bytes");
  m.data_bytes = r.u32("data_bytes");
  m.data_crc32 = r.u32("data_crc32");
  if (auto s = finish(r, "swath_header"); !s) return fail(s.error());
  const std::string where = "swath_header (swath " + std::to_string(h.index) + ")";
  if (dir > 1) return malformed(where.c_str(), "direction " + std::to_string(dir) + " out of range");
  if (comp > 1) return malformed(where.c_str(), "compression " + std::to_string(comp) + " out of range");
  h.direction = static_cast<CarriageDirection>(dir);
  h.compression = static_cast<SwathCompression>(comp);
  return m;
}

void encode(const SwathDataMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u32(m.swath_index);
  w.u32(m.offset);
  w.bytes(m.data);
}

Result<SwathDataMsg> decode_swath_data(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  SwathDataMsg m;
  m.swath_index = r.u32("swath_index");
  m.offset = r.u32("offset");
  if (!r.ok()) return malformed("swath_data", std::string("field '") + r.failed_field() + "' truncated");
  m.data = r.rest();
  return m;
}

void encode(const FeedMsg& m, std::vector<std::uint8_t>& out) { ByteWriter(out).u32(m.feed_um); }

Result<FeedMsg> decode_feed(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  FeedMsg m;
  m.feed_um = r.u32("feed_um");
  if (auto s = finish(r, "feed"); !s) return fail(s.error());
  return m;
}

void encode(const CutterCueMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u32(m.cue_id);
  w.u8(static_cast<std::uint8_t>(m.kind));
  w.i64(m.position_um);
  w.i32(m.x_um);
}

Result<CutterCueMsg> decode_cutter_cue(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  CutterCueMsg m;
  m.cue_id = r.u32("cue_id");
  const std::uint8_t kind = r.u8("kind");
  m.position_um = r.i64("position_um");
  m.x_um = r.i32("x_um");
  if (auto s = finish(r, "cutter_cue"); !s) return fail(s.error());
  if (kind > 1) return malformed("cutter_cue", "kind " + std::to_string(kind) + " out of range");
  if (m.cue_id == 0) return malformed("cutter_cue", "cue_id 0 is reserved");
  m.kind = static_cast<CueKind>(kind);
  return m;
}

void encode(const CueDoneMsg& m, std::vector<std::uint8_t>& out) { ByteWriter(out).u32(m.cue_id); }

Result<CueDoneMsg> decode_cue_done(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  CueDoneMsg m;
  m.cue_id = r.u32("cue_id");
  if (auto s = finish(r, "cue_done"); !s) return fail(s.error());
  return m;
}

void encode(const AbortMsg& m, std::vector<std::uint8_t>& out) { ByteWriter(out).str(m.reason); }

Result<AbortMsg> decode_abort(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  AbortMsg m;
  m.reason = r.str("reason");
  if (auto s = finish(r, "abort"); !s) return fail(s.error());
  return m;
}

void encode(const StatusMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u32(m.ack_seq);
  w.u32(m.naks);
  w.u8(static_cast<std::uint8_t>(m.state));
  w.u16(static_cast<std::uint16_t>(m.condition));
  w.u64(m.job_id);
  w.u32(m.swath_next);
  w.u32(m.printed_next);
  w.u16(m.free_slots);
  w.u32(m.free_bytes);
  w.i64(m.fabric_pos_um);
  w.u32(m.cue_waiting);
  w.u32(m.cues_registered);
  w.u64(m.last_job_id);
  w.u8(static_cast<std::uint8_t>(m.last_outcome));
  w.u32(m.rx_crc_errors);
  w.u32(m.rx_gaps);
  w.i64(m.printed_fabric_um);
  w.i64(m.queued_fabric_um);
  w.u32(m.last_printed_next);
  w.i64(m.last_printed_fabric_um);
  w.i64(m.last_fabric_pos_um);
}

Result<StatusMsg> decode_status(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  StatusMsg m;
  m.ack_seq = r.u32("ack_seq");
  m.naks = r.u32("naks");
  const std::uint8_t state = r.u8("state");
  const std::uint16_t cond = r.u16("condition");
  m.job_id = r.u64("job_id");
  m.swath_next = r.u32("swath_next");
  m.printed_next = r.u32("printed_next");
  m.free_slots = r.u16("free_slots");
  m.free_bytes = r.u32("free_bytes");
  m.fabric_pos_um = r.i64("fabric_pos_um");
  m.cue_waiting = r.u32("cue_waiting");
  m.cues_registered = r.u32("cues_registered");
  m.last_job_id = r.u64("last_job_id");
  const std::uint8_t outcome = r.u8("last_outcome");
  m.rx_crc_errors = r.u32("rx_crc_errors");
  m.rx_gaps = r.u32("rx_gaps");
  m.printed_fabric_um = r.i64("printed_fabric_um");
  m.queued_fabric_um = r.i64("queued_fabric_um");
  m.last_printed_next = r.u32("last_printed_next");
  m.last_printed_fabric_um = r.i64("last_printed_fabric_um");
  m.last_fabric_pos_um = r.i64("last_fabric_pos_um");
  if (auto s = finish(r, "status"); !s) return fail(s.error());
  if (!valid_state(state)) return malformed("status", "state " + std::to_string(state) + " out of range");
  if (!valid_condition(cond)) return malformed("status", "condition " + std::to_string(cond) + " out of range");
  if (!valid_outcome(outcome)) return malformed("status", "last_outcome " + std::to_string(outcome) + " out of range");
  m.state = static_cast<PrinterState>(state);
  m.condition = static_cast<PrinterCondition>(cond);
  m.last_outcome = static_cast<JobOutcome>(outcome);
  return m;
}

void encode(const RejectMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u8(static_cast<std::uint8_t>(m.refused));
  w.u32(m.seq);
  w.u16(static_cast<std::uint16_t>(m.code));
  w.str(m.message);
}

Result<RejectMsg> decode_reject(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  RejectMsg m;
  const std::uint8_t refused = r.u8("refused");
  m.seq = r.u32("seq");
  const std::uint16_t code = r.u16("code");
  m.message = r.str("message");
  if (auto s = finish(r, "reject"); !s) return fail(s.error());
  if (!is_message_type(refused)) return malformed("reject", "refused type " + std::to_string(refused) + " unknown");
  if (to_string(static_cast<ErrorCode>(code)) == "unknown")
    return malformed("reject", "code " + std::to_string(code) + " unknown");
  m.refused = static_cast<MessageType>(refused);
  m.code = static_cast<ErrorCode>(code);
  return m;
}

void encode(const JobReportMsg& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u64(m.job_id);
  w.str(m.name);
  w.u8(static_cast<std::uint8_t>(m.outcome));
  w.u16(static_cast<std::uint16_t>(m.condition));
  w.u32(m.first_swath);
  w.u32(m.swaths_printed);
  w.i64(m.feed_travel_um);
  w.u64(m.print_time_us);
  w.u32(m.cues_fired);
  w.u32(m.overruns);
  w.u8(static_cast<std::uint8_t>(m.drops_per_ink.size()));
  for (auto d : m.drops_per_ink) w.u64(d);
}

Result<JobReportMsg> decode_job_report(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  JobReportMsg m;
  m.job_id = r.u64("job_id");
  m.name = r.str("name");
  const std::uint8_t outcome = r.u8("outcome");
  const std::uint16_t cond = r.u16("condition");
  m.first_swath = r.u32("first_swath");
  m.swaths_printed = r.u32("swaths_printed");
  m.feed_travel_um = r.i64("feed_travel_um");
  m.print_time_us = r.u64("print_time_us");
  m.cues_fired = r.u32("cues_fired");
  m.overruns = r.u32("overruns");
  const std::size_t n_inks = r.u8("ink_count");
  if (n_inks > kMaxInks) return malformed("job_report", std::to_string(n_inks) + " inks (limit 16)");
  for (std::size_t i = 0; i < n_inks && r.ok(); ++i) m.drops_per_ink.push_back(r.u64("drops"));
  if (auto s = finish(r, "job_report"); !s) return fail(s.error());
  if (!valid_outcome(outcome)) return malformed("job_report", "outcome " + std::to_string(outcome) + " out of range");
  if (!valid_condition(cond)) return malformed("job_report", "condition " + std::to_string(cond) + " out of range");
  m.outcome = static_cast<JobOutcome>(outcome);
  m.condition = static_cast<PrinterCondition>(cond);
  return m;
}

}  // namespace tp::device
