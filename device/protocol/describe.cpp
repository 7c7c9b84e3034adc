// device/protocol/describe.cpp: textual rendering of frames and recordings.
#include "device/protocol/describe.h"

#include <cinttypes>
#include <cstdio>
#include <string>
#include <type_traits>

#include "device/protocol/messages.h"

namespace tp::device {

namespace {

std::string quote_text(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

// ---- The fields of each message as the dump shows them. ----

std::string text(const HelloMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b, " versions=%u..%u max_payload=%u host=", m.min_version, m.max_version,
                m.max_payload_bytes);
  return b + quote_text(m.host);
}

std::string text(const IdentifyMsg& m) {
  char b[512];
  std::string inks;
  for (const auto& i : m.inks) inks += (inks.empty() ? "" : ",") + i;
  std::snprintf(b, sizeof b,
                " protocol=%u (speaks %u..%u) dpi=%dx%d nozzles=%u bpp=%u slots=%u buffer=%u width_um=%u "
                "max_payload=%u inks=",
                m.protocol_version, m.min_version, m.max_version, m.dpi_x, m.dpi_y, m.nozzles_per_ink, m.bits_per_pixel,
                m.swath_slots, m.swath_buffer_bytes, m.print_width_um, m.max_payload_bytes);
  return b + inks + " model=" + quote_text(m.model) + " firmware=" + quote_text(m.firmware) +
         " ieee1284=" + quote_text(m.ieee1284_id);
}

std::string text(const JobBeginMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b, " job=%" PRIu64 " first_swath=%u fabric_width_px=%u fabric_um=%" PRId64 " name=", m.job_id,
                m.first_swath, m.fabric_width_px, m.fabric_pos_um);
  return b + quote_text(m.name);
}

std::string text(const JobEndMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b, " swaths=%u final_feed_um=%u", m.swath_count, m.final_feed_um);
  return b;
}

std::string text(const SwathHeaderMsg& m) {
  char b[512];
  const auto& h = m.header;
  std::snprintf(b, sizeof b,
                " swath=%u pass=%u dir=%s first_row=%" PRId64
                " rows=%u row_step=%u x=%d width=%u ch=%u bpp=%u "
                "feed_um=%u comp=%s raw=%u data=%u crc=0x%08x",
                h.index, h.pass, h.direction == CarriageDirection::kLeftToRight ? "ltr" : "rtl", h.first_row, h.rows,
                h.row_step, h.x_start_px, h.width_px, h.channels, h.bits_per_pixel, h.feed_before_um,
                h.compression == SwathCompression::kNone ? "none" : "packbits", h.raw_bytes, m.data_bytes,
                m.data_crc32);
  return b;
}

std::string text(const SwathDataMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b, " swath=%u offset=%u bytes=%zu", m.swath_index, m.offset, m.data.size());
  return b;
}

std::string text(const FeedMsg& m) { return " feed_um=" + std::to_string(m.feed_um); }

std::string text(const CutterCueMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b, " cue=%u kind=%s position_um=%" PRId64 " x_um=%d", m.cue_id,
                std::string(to_string(m.kind)).c_str(), m.position_um, m.x_um);
  return b;
}

std::string text(const CueDoneMsg& m) { return " cue=" + std::to_string(m.cue_id); }

std::string text(const AbortMsg& m) { return " reason=" + quote_text(m.reason); }

std::string text(const StatusMsg& m) {
  char b[512];
  std::snprintf(b, sizeof b,
                " ack=%u naks=%u state=%s cond=%s job=%" PRIu64
                " swath_next=%u printed_next=%u slots=%u "
                "free=%u fabric_um=%" PRId64 " cue_waiting=%u cues=%u last_job=%" PRIu64
                " outcome=%s rx_crc_errors=%u rx_gaps=%u printed_um=%" PRId64 " queued_um=%" PRId64
                " last_printed_next=%u last_printed_um=%" PRId64 " last_fabric_um=%" PRId64,
                m.ack_seq, m.naks, std::string(to_string(m.state)).c_str(), std::string(to_string(m.condition)).c_str(),
                m.job_id, m.swath_next, m.printed_next, m.free_slots, m.free_bytes, m.fabric_pos_um, m.cue_waiting,
                m.cues_registered, m.last_job_id, std::string(to_string(m.last_outcome)).c_str(), m.rx_crc_errors,
                m.rx_gaps, m.printed_fabric_um, m.queued_fabric_um, m.last_printed_next, m.last_printed_fabric_um,
                m.last_fabric_pos_um);
  return b;
}

std::string text(const RejectMsg& m) {
  return " refused=" + std::string(to_string(m.refused)) + " seq=" + std::to_string(m.seq) +
         " code=" + std::string(to_string(m.code)) + " message=" + quote_text(m.message);
}

std::string text(const JobReportMsg& m) {
  char b[512];
  std::string drops;
  for (auto d : m.drops_per_ink) drops += (drops.empty() ? "" : ",") + std::to_string(d);
  std::snprintf(b, sizeof b,
                " job=%" PRIu64 " outcome=%s cond=%s first_swath=%u printed=%u feed_um=%" PRId64 " time_us=%" PRIu64
                " cues=%u overruns=%u drops=",
                m.job_id, std::string(to_string(m.outcome)).c_str(), std::string(to_string(m.condition)).c_str(),
                m.first_swath, m.swaths_printed, m.feed_travel_um, m.print_time_us, m.cues_fired, m.overruns);
  return b + drops + " name=" + quote_text(m.name);
}

// Messages without payload show only an unexpected one.
std::string empty_text(std::span<const std::uint8_t> p) {
  return p.empty() ? "" : " (" + std::to_string(p.size()) + " unexpected payload bytes)";
}

template <class M, class Decode>
std::string payload_text(std::span<const std::uint8_t> p, Decode decode) {
  if constexpr (std::is_empty_v<M>) {
    return empty_text(p);
  } else {
    auto m = decode(p);
    if (!m) return "malformed: " + m.error().message;
    return text(*m);
  }
}

std::string fields(const Frame& f) {
  switch (f.header.type) {
#define TP_MESSAGE_DESCRIBE(name, code, wire, Payload) \
  case MessageType::name: return payload_text<Payload>(f.payload, decode_##wire);
    TP_PROTOCOL_MESSAGES(TP_MESSAGE_DESCRIBE)
#undef TP_MESSAGE_DESCRIBE
  }
  return " (unknown type)";
}

}  // namespace

std::string describe_frame(const Frame& frame) {
  std::string s = std::string(to_string(frame.header.type)) + " #" + std::to_string(frame.header.seq);
  if (frame.header.flags & kFrameFlagRetransmit) s += " (resent)";
  std::string f = fields(frame);
  if (f.rfind("malformed", 0) == 0) return s + " " + f;
  return s + f;
}

std::string dump_recording(const std::vector<WireRecord>& records, const DumpOptions& options) {
  FrameDecoder to_printer, to_host;
  std::string out;
  for (const auto& rec : records) {
    std::string prefix;
    if (options.times) {
      char t[32];
      std::snprintf(t, sizeof t, "%.6f ", static_cast<double>(rec.time_us) / 1e6);
      prefix = t;
    }
    if (rec.kind == RecordKind::kEvent) {
      out += prefix + "--- " + std::string(rec.bytes.begin(), rec.bytes.end()) + "\n";
      // A link event starts both byte streams afresh.
      to_printer.reset();
      to_host.reset();
      continue;
    }
    const bool h2p = rec.kind == RecordKind::kHostToPrinter;
    FrameDecoder& dec = h2p ? to_printer : to_host;
    const std::string dir = h2p ? "H>P " : "P>H ";
    dec.feed(rec.bytes);
    while (auto r = dec.next()) {
      if (*r) out += prefix + dir + describe_frame(**r) + "\n";
      else out += prefix + dir + "error: " + r->error().message + "\n";
    }
  }
  return out;
}

}  // namespace tp::device
