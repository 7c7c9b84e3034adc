// device/protocol/host_link.h: the host's end of the link: handshake, reliable in-order delivery
// of messages (sequence numbers, cumulative acks, go-back-N resend on NAK or timeout) and the
// latest printer status. Swath-level credits and jobs are the print session's business
// (host/session); this class only moves frames.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "device/common/error.h"
#include "device/protocol/frame.h"
#include "device/protocol/messages.h"
#include "device/protocol/transport.h"
#include "device/swath/swath.h"

namespace tp::device {

struct LinkOptions {
  std::chrono::milliseconds handshake_timeout{1500};  ///< per hello attempt
  int handshake_attempts = 3;
  std::chrono::milliseconds retransmit_timeout{500};  ///< resend unacknowledged frames after this
  std::chrono::milliseconds dead_link_timeout{15000}; ///< no ack progress this long: kTimeout
  std::size_t max_unacked_bytes = 16u << 20;          ///< frames in flight before send() waits
  /// Data bytes per swath_data frame; the default makes each frame exactly 256 KiB on the wire.
  std::uint32_t chunk_bytes = (256u << 10) - kFrameOverheadBytes - kSwathDataOverheadBytes;
  std::string host_name = "tp-host";
};

struct LinkStats {
  std::uint64_t frames_sent = 0;
  std::uint64_t frames_resent = 0;
  std::uint64_t bytes_sent = 0;     ///< including resent bytes
  std::uint64_t bytes_resent = 0;
  std::uint64_t naks_seen = 0;      ///< resend requests from the printer
  std::uint64_t timeouts = 0;       ///< resends triggered by the retransmit timer
  std::uint64_t statuses = 0;
  std::uint64_t rx_errors = 0;      ///< corrupt frames from the printer
};

class HostLink {
 public:
  explicit HostLink(Transport& transport, LinkOptions options = {});

  /// Resets the transport and the link, sends hello and waits for identify. Fails with
  /// kIncompatiblePrinter if the printer speaks no version in kProtocolVersionMin..Max (the
  /// message names the printer's model and versions), kTimeout if it never answers, or the
  /// transport's error.
  [[nodiscard]] Result<IdentifyMsg> handshake();

  /// Sends one message; it is resent until acknowledged. Blocks (polling the printer) while
  /// max_unacked_bytes are in flight. Fails with the transport's error or kTimeout on a dead link.
  [[nodiscard]] Status send(MessageType type, std::span<const std::uint8_t> payload);
  template <class Msg>
  [[nodiscard]] Status send_msg(MessageType type, const Msg& msg) {
    std::vector<std::uint8_t> payload;
    encode(msg, payload);
    return send(type, payload);
  }

  /// Sends a swath: its header, then its data in chunk_bytes pieces.
  [[nodiscard]] Status send_swath(const Swath& swath);

  /// Reads what the printer sent, waiting up to `timeout` for the first bytes, and handles it:
  /// acknowledgements free resend buffers, NAKs and the retransmit timer resend.
  [[nodiscard]] Status poll(std::chrono::milliseconds timeout);

  /// Polls until every frame sent so far is acknowledged; kTimeout after `timeout`.
  [[nodiscard]] Status drain(std::chrono::milliseconds timeout);

  /// Asks for a status and waits for one that reflects the query; kTimeout after `timeout`.
  [[nodiscard]] Result<StatusMsg> query_status(std::chrono::milliseconds timeout);

  /// The latest status (nullptr before the first after a handshake).
  [[nodiscard]] const StatusMsg* status() const { return has_status_ ? &status_ : nullptr; }
  /// Increments with every status received; lets callers wait for a fresh one.
  [[nodiscard]] std::uint64_t status_serial() const { return status_serial_; }
  [[nodiscard]] const IdentifyMsg& identity() const { return identity_; }
  /// A refusal the printer sent since the last call, if any.
  std::optional<RejectMsg> take_reject();
  /// A job report the printer sent since the last call, if any.
  std::optional<JobReportMsg> take_report();

  [[nodiscard]] const LinkStats& stats() const { return stats_; }
  [[nodiscard]] std::size_t unacked_bytes() const { return unacked_bytes_; }
  [[nodiscard]] std::uint32_t next_seq() const { return next_seq_; }
  [[nodiscard]] const LinkOptions& options() const { return options_; }
  [[nodiscard]] Transport& transport() { return transport_; }

 private:
  struct SentFrame {
    std::uint32_t seq;
    std::vector<std::uint8_t> bytes;
  };
  [[nodiscard]] Status transmit(std::vector<std::uint8_t> frame_bytes, std::uint32_t seq);
  [[nodiscard]] Status resend_unacked();
  [[nodiscard]] Status read_available(std::chrono::milliseconds timeout);
  void handle_frame(Frame frame);
  void on_status(const StatusMsg& status);
  [[nodiscard]] Status check_timers();

  Transport& transport_;
  LinkOptions options_;
  FrameDecoder decoder_;
  std::vector<std::uint8_t> rx_buffer_;
  std::deque<SentFrame> unacked_;
  std::size_t unacked_bytes_ = 0;
  std::uint32_t next_seq_ = 1;
  std::uint32_t naks_seen_ = 0;
  std::chrono::steady_clock::time_point last_progress_;
  std::chrono::steady_clock::time_point last_resend_;
  StatusMsg status_;
  bool has_status_ = false;
  std::uint64_t status_serial_ = 0;
  bool have_identity_ = false;
  IdentifyMsg identity_;
  std::optional<RejectMsg> reject_;
  std::optional<JobReportMsg> report_;
  LinkStats stats_;
};

}  // namespace tp::device
