// device/protocol/messages.cpp: each message's fields listed once, in wire order, walked by one
// encoder and one validating decoder.
#include "device/protocol/messages.h"

#include <string>
#include <type_traits>

#include "device/protocol/internal/byte_io.h"

namespace tp::device {

using wire::ByteReader;
using wire::ByteWriter;

namespace {

// Upper bounds that keep a corrupt or hostile payload from asking for absurd allocations.
constexpr std::size_t kMaxInks = 16;

std::unexpected<Error> malformed(const std::string& msg, const std::string& what) {
  return fail(ErrorCode::kMalformedFrame, msg + ": " + what);
}

// The unsigned integer of the same width as a field's type (enums by their underlying type).
template <class T>
using WireUnsigned = std::make_unsigned_t<
    typename std::conditional_t<std::is_enum_v<T>, std::underlying_type<T>, std::type_identity<T>>::type>;

// Walks a message's field list and appends each field to the payload.
class Encoder {
 public:
  explicit Encoder(std::vector<std::uint8_t>& out) : w_(out) {}
  template <class T>
  void field(const T& v, const char* /*name*/) {
    const auto u = static_cast<WireUnsigned<T>>(v);
    if constexpr (sizeof u == 1)
      w_.u8(u);
    else if constexpr (sizeof u == 2)
      w_.u16(u);
    else if constexpr (sizeof u == 4)
      w_.u32(u);
    else
      w_.u64(u);
  }
  void text(const std::string& s, const char* /*name*/) { w_.str(s); }
  /// A u8 count, then the items.
  template <class T>
  void list(const std::vector<T>& items, const char* /*count*/, const char* item, const char* /*noun*/) {
    w_.u8(static_cast<std::uint8_t>(items.size()));
    for (const auto& x : items) {
      if constexpr (std::is_same_v<T, std::string>)
        text(x, item);
      else
        field(x, item);
    }
  }
  void rest(const std::span<const std::uint8_t>& data) { w_.bytes(data); }

 private:
  ByteWriter w_;
};

// Walks a message's field list and reads each field from the payload; the first truncated field
// or over-long list is kept for finish().
class Decoder {
 public:
  explicit Decoder(std::span<const std::uint8_t> in) : r_(in) {}
  template <class T>
  void field(T& v, const char* name) {
    using U = WireUnsigned<T>;
    U u;
    if constexpr (sizeof(U) == 1)
      u = r_.u8(name);
    else if constexpr (sizeof(U) == 2)
      u = r_.u16(name);
    else if constexpr (sizeof(U) == 4)
      u = r_.u32(name);
    else
      u = r_.u64(name);
    v = static_cast<T>(u);
  }
  void text(std::string& s, const char* name) { s = r_.str(name); }
  template <class T>
  void list(std::vector<T>& items, const char* count, const char* item, const char* noun) {
    const std::size_t n = r_.u8(count);
    if (n > kMaxInks) {
      if (limit_.empty()) limit_ = std::to_string(n) + " " + noun + " (limit " + std::to_string(kMaxInks) + ")";
      return;
    }
    for (std::size_t i = 0; i < n && r_.ok(); ++i) {
      T x{};
      if constexpr (std::is_same_v<T, std::string>)
        text(x, item);
      else
        field(x, item);
      items.push_back(std::move(x));
    }
  }
  void rest(std::span<const std::uint8_t>& data) { data = r_.rest(); }

  /// Ends a decode: an over-long list, a truncated field or trailing bytes make it malformed.
  Status finish(const char* msg) const {
    if (!limit_.empty()) return malformed(msg, limit_);
    if (!r_.ok()) return malformed(msg, std::string("field '") + r_.failed_field() + "' truncated");
    if (r_.remaining() != 0) return malformed(msg, std::to_string(r_.remaining()) + " unexpected trailing bytes");
    return {};
  }

 private:
  ByteReader r_;
  std::string limit_;
};

// ---- The field lists: one per message, in wire order. ----

template <class IO>
void fields(IO& io, HelloMsg& m) {
  io.field(m.min_version, "min_version");
  io.field(m.max_version, "max_version");
  io.field(m.max_payload_bytes, "max_payload_bytes");
  io.text(m.host, "host");
}

template <class IO>
void fields(IO& io, IdentifyMsg& m) {
  io.field(m.protocol_version, "protocol_version");
  io.field(m.min_version, "min_version");
  io.field(m.max_version, "max_version");
  io.text(m.model, "model");
  io.text(m.ieee1284_id, "ieee1284_id");
  io.text(m.firmware, "firmware");
  io.field(m.max_payload_bytes, "max_payload_bytes");
  io.field(m.dpi_x, "dpi_x");
  io.field(m.dpi_y, "dpi_y");
  io.field(m.nozzles_per_ink, "nozzles_per_ink");
  io.field(m.bits_per_pixel, "bits_per_pixel");
  io.list(m.inks, "ink_count", "ink_name", "inks");
  io.field(m.swath_slots, "swath_slots");
  io.field(m.swath_buffer_bytes, "swath_buffer_bytes");
  io.field(m.print_width_um, "print_width_um");
}

template <class IO>
void fields(IO& io, JobBeginMsg& m) {
  io.field(m.job_id, "job_id");
  io.text(m.name, "name");
  io.field(m.first_swath, "first_swath");
  io.field(m.fabric_width_px, "fabric_width_px");
  io.field(m.fabric_pos_um, "fabric_pos_um");
}

template <class IO>
void fields(IO& io, JobEndMsg& m) {
  io.field(m.swath_count, "swath_count");
  io.field(m.final_feed_um, "final_feed_um");
}

template <class IO>
void fields(IO& io, SwathHeaderMsg& m) {
  SwathHeader& h = m.header;
  io.field(h.index, "index");
  io.field(h.pass, "pass");
  io.field(h.direction, "direction");
  io.field(h.first_row, "first_row");
  io.field(h.row_step, "row_step");
  io.field(h.rows, "rows");
  io.field(h.x_start_px, "x_start_px");
  io.field(h.width_px, "width_px");
  io.field(h.channels, "channels");
  io.field(h.bits_per_pixel, "bits_per_pixel");
  io.field(h.feed_before_um, "feed_before_um");
  io.field(h.compression, "compression");
  io.field(h.raw_bytes, "raw_bytes");
  io.field(m.data_bytes, "data_bytes");
  io.field(m.data_crc32, "data_crc32");
}

template <class IO>
void fields(IO& io, SwathDataMsg& m) {
  io.field(m.swath_index, "swath_index");
  io.field(m.offset, "offset");
  io.rest(m.data);
}

template <class IO>
void fields(IO& io, FeedMsg& m) {
  io.field(m.feed_um, "feed_um");
}

template <class IO>
void fields(IO& io, CutterCueMsg& m) {
  io.field(m.cue_id, "cue_id");
  io.field(m.kind, "kind");
  io.field(m.position_um, "position_um");
  io.field(m.x_um, "x_um");
}

template <class IO>
void fields(IO& io, CueDoneMsg& m) {
  io.field(m.cue_id, "cue_id");
}

template <class IO>
void fields(IO& io, AbortMsg& m) {
  io.text(m.reason, "reason");
}

template <class IO>
void fields(IO& io, StatusMsg& m) {
  io.field(m.ack_seq, "ack_seq");
  io.field(m.naks, "naks");
  io.field(m.state, "state");
  io.field(m.condition, "condition");
  io.field(m.job_id, "job_id");
  io.field(m.swath_next, "swath_next");
  io.field(m.printed_next, "printed_next");
  io.field(m.free_slots, "free_slots");
  io.field(m.free_bytes, "free_bytes");
  io.field(m.fabric_pos_um, "fabric_pos_um");
  io.field(m.cue_waiting, "cue_waiting");
  io.field(m.cues_registered, "cues_registered");
  io.field(m.last_job_id, "last_job_id");
  io.field(m.last_outcome, "last_outcome");
  io.field(m.rx_crc_errors, "rx_crc_errors");
  io.field(m.rx_gaps, "rx_gaps");
  io.field(m.printed_fabric_um, "printed_fabric_um");
  io.field(m.queued_fabric_um, "queued_fabric_um");
  io.field(m.last_printed_next, "last_printed_next");
  io.field(m.last_printed_fabric_um, "last_printed_fabric_um");
  io.field(m.last_fabric_pos_um, "last_fabric_pos_um");
}

template <class IO>
void fields(IO& io, RejectMsg& m) {
  io.field(m.refused, "refused");
  io.field(m.seq, "seq");
  io.field(m.code, "code");
  io.text(m.message, "message");
}

template <class IO>
void fields(IO& io, JobReportMsg& m) {
  io.field(m.job_id, "job_id");
  io.text(m.name, "name");
  io.field(m.outcome, "outcome");
  io.field(m.condition, "condition");
  io.field(m.first_swath, "first_swath");
  io.field(m.swaths_printed, "swaths_printed");
  io.field(m.feed_travel_um, "feed_travel_um");
  io.field(m.print_time_us, "print_time_us");
  io.field(m.cues_fired, "cues_fired");
  io.field(m.overruns, "overruns");
  io.list(m.drops_per_ink, "ink_count", "drops", "inks");
}

// Messages without payload have no fields.
template <class IO>
void fields(IO&, StatusQueryMsg&) {}
template <class IO>
void fields(IO&, ReportQueryMsg&) {}
template <class IO>
void fields(IO&, PauseMsg&) {}
template <class IO>
void fields(IO&, ResumeMsg&) {}

// ---- Checks of decoded values beyond their layout (enum ranges, reserved values). ----

bool valid(PrinterState v) { return v <= PrinterState::kAborting; }
bool valid(PrinterCondition v) { return to_string(v) != "unknown"; }
bool valid(JobOutcome v) { return v <= JobOutcome::kLost; }
bool valid(CueKind v) { return v <= CueKind::kNotch; }
bool valid(CarriageDirection v) { return v <= CarriageDirection::kRightToLeft; }
bool valid(SwathCompression v) { return v <= SwathCompression::kPackBits; }

template <class E>
std::string number(E v) {
  return std::to_string(static_cast<WireUnsigned<E>>(v));
}

// Fails with "<field> <value> out of range" if an enum field holds a value outside its type.
template <class E>
Status in_range(const std::string& msg, const char* field, E v) {
  if (!valid(v)) return malformed(msg, std::string(field) + " " + number(v) + " out of range");
  return {};
}

template <class M>
Status check(const M&) {
  return {};
}

Status check(const HelloMsg& m) {
  if (m.min_version > m.max_version)
    return malformed("hello", "min_version " + std::to_string(m.min_version) + " above max_version " +
                                  std::to_string(m.max_version));
  return {};
}

Status check(const SwathHeaderMsg& m) {
  const std::string where = "swath_header (swath " + std::to_string(m.header.index) + ")";
  if (auto s = in_range(where, "direction", m.header.direction); !s) return s;
  return in_range(where, "compression", m.header.compression);
}

Status check(const CutterCueMsg& m) {
  if (auto s = in_range("cutter_cue", "kind", m.kind); !s) return s;
  if (m.cue_id == 0) return malformed("cutter_cue", "cue_id 0 is reserved");
  return {};
}

Status check(const StatusMsg& m) {
  if (auto s = in_range("status", "state", m.state); !s) return s;
  if (auto s = in_range("status", "condition", m.condition); !s) return s;
  return in_range("status", "last_outcome", m.last_outcome);
}

Status check(const RejectMsg& m) {
  if (!is_message_type(static_cast<std::uint8_t>(m.refused)))
    return malformed("reject", "refused type " + number(m.refused) + " unknown");
  if (to_string(m.code) == "unknown") return malformed("reject", "code " + number(m.code) + " unknown");
  return {};
}

Status check(const JobReportMsg& m) {
  if (auto s = in_range("job_report", "outcome", m.outcome); !s) return s;
  return in_range("job_report", "condition", m.condition);
}

template <class M>
void encode_fields(const M& m, std::vector<std::uint8_t>& out) {
  Encoder e(out);
  fields(e, const_cast<M&>(m));  // the encoder only reads the fields
}

template <class M>
Result<M> decode_fields(std::span<const std::uint8_t> payload, const char* msg) {
  Decoder d(payload);
  M m{};
  fields(d, m);
  if (auto s = d.finish(msg); !s) return fail(s.error());
  if (auto s = check(m); !s) return fail(s.error());
  return m;
}

}  // namespace

#define TP_MESSAGE_CODEC(name, code, wire, Payload)                                        \
  void encode(const Payload& m, std::vector<std::uint8_t>& out) { encode_fields(m, out); } \
  Result<Payload> decode_##wire(std::span<const std::uint8_t> payload) {                   \
    return decode_fields<Payload>(payload, #wire);                                         \
  }
TP_PROTOCOL_MESSAGES(TP_MESSAGE_CODEC)
#undef TP_MESSAGE_CODEC

}  // namespace tp::device
