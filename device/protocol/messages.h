// device/protocol/messages.h: the payloads of every protocol message and their encoding.
//
// Each message of message_table.h has a struct here; messages.cpp lists its fields once, in wire
// order, and derives from that list the encoder (appends the payload to a byte vector) and the
// decoder (checks lengths and enum values and names the offending field on failure). Frames wrap
// these payloads (frame.h); docs/protocol.md describes the exchange.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "device/common/error.h"
#include "device/protocol/frame.h"
#include "device/protocol/status_codes.h"
#include "device/swath/swath.h"

namespace tp::device {

/// Protocol versions this build speaks (host and firmware alike).
inline constexpr std::uint16_t kProtocolVersionMin = 1;
inline constexpr std::uint16_t kProtocolVersionMax = 1;

struct HelloMsg {
  std::uint16_t min_version = kProtocolVersionMin;
  std::uint16_t max_version = kProtocolVersionMax;
  std::uint32_t max_payload_bytes = kMaxFramePayloadBytes;  ///< largest frame the host accepts
  std::string host;                                         ///< host name, for the printer's log
};

/// The printer's answer to hello.
struct IdentifyMsg {
  std::uint16_t protocol_version = kProtocolVersionMax;  ///< 0 if no version in the host's range
  std::uint16_t min_version = kProtocolVersionMin;       ///< oldest version the printer speaks
  std::uint16_t max_version = kProtocolVersionMax;       ///< newest version the printer speaks
  std::string model;
  std::string ieee1284_id;
  std::string firmware;
  std::uint32_t max_payload_bytes = kMaxFramePayloadBytes;
  std::int32_t dpi_x = 0;
  std::int32_t dpi_y = 0;
  std::uint16_t nozzles_per_ink = 0;
  std::uint8_t bits_per_pixel = 0;
  std::vector<std::string> inks;
  std::uint16_t swath_slots = 0;
  std::uint32_t swath_buffer_bytes = 0;
  std::uint32_t print_width_um = 0;
};

struct JobBeginMsg {
  std::uint64_t job_id = 0;
  std::string name;
  std::uint32_t first_swath = 0;      ///< index of the first swath the host will send (resume)
  std::uint32_t fabric_width_px = 0;  ///< width of the marker at dpi_x (0: the print width)
  /// Where the fabric stands, from the job's start, as the job (re)opens: 0 for a new job; after the
  /// printer lost the job, the position it reported, so cue and feed positions stay continuous.
  std::int64_t fabric_pos_um = 0;
};

struct JobEndMsg {
  std::uint32_t swath_count = 0;    ///< swaths in the whole job (indices 0..count-1)
  std::uint32_t final_feed_um = 0;  ///< fabric advance after the last swath
};

struct SwathHeaderMsg {
  SwathHeader header;
  std::uint32_t data_bytes = 0;  ///< bytes of (compressed) data that follow in kSwathData chunks
  std::uint32_t data_crc32 = 0;  ///< CRC-32 of those bytes
};

/// One chunk of swath data; `data` views the frame payload it was decoded from.
struct SwathDataMsg {
  std::uint32_t swath_index = 0;
  std::uint32_t offset = 0;  ///< byte offset of this chunk in the swath's data
  std::span<const std::uint8_t> data;
};

struct FeedMsg {
  std::uint32_t feed_um = 0;
};

struct CutterCueMsg {
  std::uint32_t cue_id = 0;        ///< 1-based, increasing within a job
  CueKind kind = CueKind::kCut;
  std::int64_t position_um = 0;    ///< fabric position (from the job's start) that triggers it
  std::int32_t x_um = 0;           ///< across-fabric position, for notch markers
};

struct CueDoneMsg {
  std::uint32_t cue_id = 0;
};

struct AbortMsg {
  std::string reason;
};

/// The printer's state as of this report. All counts are cumulative so that a lost report is
/// made good by the next one.
struct StatusMsg {
  std::uint32_t ack_seq = 0;    ///< next host sequence number expected: all before arrived intact
  std::uint32_t naks = 0;       ///< receive errors so far; a rise asks the host to resend from ack_seq
  PrinterState state = PrinterState::kIdle;
  PrinterCondition condition = PrinterCondition::kNone;
  std::uint64_t job_id = 0;
  std::uint32_t swath_next = 0;    ///< swaths below this index are received, checked and committed
  std::uint32_t printed_next = 0;  ///< swaths below this index are printed
  std::uint16_t free_slots = 0;    ///< swath buffer slots free
  std::uint32_t free_bytes = 0;    ///< swath buffer bytes free
  std::int64_t fabric_pos_um = 0;  ///< fabric advanced since the job began
  std::uint32_t cue_waiting = 0;   ///< id of the cue the printer stopped at, 0 if none
  std::uint32_t cues_registered = 0;  ///< highest cue id the printer holds
  std::uint64_t last_job_id = 0;
  JobOutcome last_outcome = JobOutcome::kNone;
  std::uint32_t rx_crc_errors = 0;
  std::uint32_t rx_gaps = 0;       ///< frames that arrived out of sequence (a frame was lost)
  // What is on the fabric, for resuming. The printer keeps these across a power loss.
  std::int64_t printed_fabric_um = 0;  ///< fabric position at which swath printed_next-1 was laid
  std::int64_t queued_fabric_um = 0;   ///< where the fabric will stand once every committed swath is fed
  std::uint32_t last_printed_next = 0;       ///< last job: swaths below this index are on the fabric
  std::int64_t last_printed_fabric_um = 0;   ///< last job: position at which its last printed swath was laid
  std::int64_t last_fabric_pos_um = 0;       ///< last job: where the fabric stood when it ended or was lost
};

struct RejectMsg {
  MessageType refused = MessageType::kHello;
  std::uint32_t seq = 0;
  ErrorCode code = ErrorCode::kBadState;
  std::string message;
};

struct JobReportMsg {
  std::uint64_t job_id = 0;
  std::string name;
  JobOutcome outcome = JobOutcome::kNone;
  PrinterCondition condition = PrinterCondition::kNone;
  std::uint32_t first_swath = 0;
  std::uint32_t swaths_printed = 0;    ///< printed in this job, including before a resume
  std::int64_t feed_travel_um = 0;
  std::uint64_t print_time_us = 0;     ///< modelled time (carriage passes and feeds)
  std::uint32_t cues_fired = 0;
  std::uint32_t overruns = 0;          ///< swaths refused for lack of credit (0 for a correct host)
  std::vector<std::uint64_t> drops_per_ink;
};

/// Messages without payload: they must arrive with an empty one.
struct StatusQueryMsg {};
struct ReportQueryMsg {};
struct PauseMsg {};
struct ResumeMsg {};

/// encode(m, out) appends a message's payload to `out`; one overload per message of
/// message_table.h.
#define TP_MESSAGE_ENCODE_DECL(name, code, wire, Payload) void encode(const Payload& m, std::vector<std::uint8_t>& out);
TP_PROTOCOL_MESSAGES(TP_MESSAGE_ENCODE_DECL)
#undef TP_MESSAGE_ENCODE_DECL

/// decode_<wire name>(payload) for every message of message_table.h. Decoders fail with
/// kMalformedFrame naming the message and field ("swath_header: field 'width_px' truncated",
/// "status: state 9 out of range").
#define TP_MESSAGE_DECODE_DECL(name, code, wire, Payload) \
  [[nodiscard]] Result<Payload> decode_##wire(std::span<const std::uint8_t> payload);
TP_PROTOCOL_MESSAGES(TP_MESSAGE_DECODE_DECL)
#undef TP_MESSAGE_DECODE_DECL

/// Payload bytes of a swath data message carrying `chunk_bytes` of data.
inline constexpr std::size_t kSwathDataOverheadBytes = 8;

}  // namespace tp::device
