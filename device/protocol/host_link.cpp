// device/protocol/host_link.cpp: handshake, reliable delivery and status tracking on the host.
#include "device/protocol/host_link.h"

#include <algorithm>

#include "device/protocol/crc.h"

namespace tp::device {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {
constexpr std::size_t kReadChunkBytes = 64u << 10;
// Bounded so a printer flooding the IN pipe cannot stall the sender forever.
constexpr int kMaxReadsPerPoll = 64;

std::string version_range(std::uint16_t lo, std::uint16_t hi) {
  return std::to_string(lo) + (lo == hi ? "" : ".." + std::to_string(hi));
}
}  // namespace

HostLink::HostLink(Transport& transport, LinkOptions options)
    : transport_(transport), options_(std::move(options)), rx_buffer_(kReadChunkBytes) {
  last_progress_ = last_resend_ = Clock::now();
}

Result<IdentifyMsg> HostLink::handshake() {
  if (auto s = transport_.reset(); !s) return fail(s.error().with_context("link reset"));
  decoder_.reset();
  unacked_.clear();
  unacked_bytes_ = 0;
  next_seq_ = 1;
  naks_seen_ = 0;
  has_status_ = false;
  have_identity_ = false;
  reject_.reset();
  report_.reset();

  HelloMsg hello;
  hello.host = options_.host_name;
  std::vector<std::uint8_t> payload;
  encode(hello, payload);
  for (int attempt = 1; attempt <= options_.handshake_attempts && !have_identity_; ++attempt) {
    std::vector<std::uint8_t> frame;
    if (auto s = encode_frame(MessageType::kHello, 0, payload, frame); !s) return fail(s.error());
    if (auto s = transport_.write(frame); !s) return fail(s.error().with_context("sending hello"));
    ++stats_.frames_sent;
    stats_.bytes_sent += frame.size();
    const auto deadline = Clock::now() + options_.handshake_timeout;
    while (!have_identity_) {
      const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      if (auto s = read_available(std::min(left, milliseconds(100))); !s)
        return fail(s.error().with_context("waiting for identify"));
    }
  }
  if (!have_identity_)
    return fail(ErrorCode::kTimeout, transport_.describe() + ": printer did not answer hello (" +
                                         std::to_string(options_.handshake_attempts) + " attempts of " +
                                         std::to_string(options_.handshake_timeout.count()) + " ms)");
  const IdentifyMsg& id = identity_;
  if (id.protocol_version < kProtocolVersionMin || id.protocol_version > kProtocolVersionMax)
    return fail(ErrorCode::kIncompatiblePrinter,
                "printer '" + id.model + "' (firmware '" + id.firmware + "') speaks protocol version " +
                    version_range(id.min_version, id.max_version) + "; this host speaks " +
                    version_range(kProtocolVersionMin, kProtocolVersionMax));
  last_progress_ = last_resend_ = Clock::now();
  return identity_;
}

Status HostLink::transmit(std::vector<std::uint8_t> frame_bytes, std::uint32_t seq) {
  if (auto s = transport_.write(frame_bytes); !s) return s;
  if (unacked_.empty()) last_progress_ = Clock::now();
  ++stats_.frames_sent;
  stats_.bytes_sent += frame_bytes.size();
  unacked_bytes_ += frame_bytes.size();
  unacked_.push_back(SentFrame{seq, std::move(frame_bytes)});
  return {};
}

Status HostLink::send(MessageType type, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> frame;
  if (auto s = encode_frame(type, next_seq_, payload, frame); !s) return s;
  // Wait for acknowledgements while the window is full; one frame may always be in flight.
  while (!unacked_.empty() && unacked_bytes_ + frame.size() > options_.max_unacked_bytes)
    if (auto s = poll(milliseconds(20)); !s) return s;
  const std::uint32_t seq = next_seq_++;
  if (auto s = transmit(std::move(frame), seq); !s) {
    --next_seq_;
    return s;
  }
  return {};
}

Status HostLink::send_swath(const Swath& swath) {
  SwathHeaderMsg hdr;
  hdr.header = swath.header;
  hdr.data_bytes = static_cast<std::uint32_t>(swath.data.size());
  hdr.data_crc32 = crc32(swath.data);
  const std::string what = "swath " + std::to_string(swath.header.index);
  if (auto s = send_msg(MessageType::kSwathHeader, hdr); !s) return fail(s.error().with_context(what));
  const std::size_t chunk = std::max<std::uint32_t>(1, options_.chunk_bytes);
  std::vector<std::uint8_t> payload;
  for (std::size_t off = 0; off < swath.data.size(); off += chunk) {
    SwathDataMsg m;
    m.swath_index = swath.header.index;
    m.offset = static_cast<std::uint32_t>(off);
    m.data = std::span(swath.data).subspan(off, std::min(chunk, swath.data.size() - off));
    payload.clear();
    encode(m, payload);
    if (auto s = send(MessageType::kSwathData, payload); !s)
      return fail(s.error().with_context(what + ": chunk at byte " + std::to_string(off)));
    // Keep up with acknowledgements and resend requests without waiting.
    if (auto s = poll(milliseconds(0)); !s) return fail(s.error().with_context(what));
  }
  return {};
}

Status HostLink::resend_unacked() {
  const auto now = Clock::now();
  for (auto& f : unacked_) {
    // Mark the frame as resent (informative for wire dumps) and re-seal its header CRC.
    if (!(f.bytes[12] & kFrameFlagRetransmit)) {
      f.bytes[12] |= kFrameFlagRetransmit;
      const std::uint16_t crc = crc16_ccitt(std::span(f.bytes.data(), 14));
      f.bytes[14] = static_cast<std::uint8_t>(crc);
      f.bytes[15] = static_cast<std::uint8_t>(crc >> 8);
    }
    if (auto s = transport_.write(f.bytes); !s) return s;
    ++stats_.frames_resent;
    ++stats_.frames_sent;
    stats_.bytes_resent += f.bytes.size();
    stats_.bytes_sent += f.bytes.size();
  }
  last_resend_ = now;
  return {};
}

Status HostLink::read_available(milliseconds timeout) {
  for (int i = 0; i < kMaxReadsPerPoll; ++i) {
    auto n = transport_.read(rx_buffer_, i == 0 ? timeout : milliseconds(0));
    if (!n) return fail(n.error());
    if (*n == 0) break;
    decoder_.feed(std::span(rx_buffer_).first(*n));
  }
  while (auto r = decoder_.next()) {
    if (*r) handle_frame(std::move(**r));
    else ++stats_.rx_errors;
  }
  return {};
}

void HostLink::handle_frame(Frame frame) {
  switch (frame.header.type) {
    case MessageType::kIdentify:
      if (auto m = decode_identify(frame.payload)) {
        identity_ = std::move(*m);
        have_identity_ = true;
      } else {
        ++stats_.rx_errors;
      }
      break;
    case MessageType::kStatus:
      // Reports sent before the printer saw our hello describe the old link: skip them.
      if (!have_identity_) break;
      if (auto m = decode_status(frame.payload)) on_status(*m);
      else ++stats_.rx_errors;
      break;
    case MessageType::kReject:
      if (auto m = decode_reject(frame.payload)) reject_ = std::move(*m);
      else ++stats_.rx_errors;
      break;
    case MessageType::kJobReport:
      if (auto m = decode_job_report(frame.payload)) report_ = std::move(*m);
      else ++stats_.rx_errors;
      break;
    default:
      // Host-bound traffic only carries printer messages; anything else is noise.
      ++stats_.rx_errors;
      break;
  }
}

void HostLink::on_status(const StatusMsg& s) {
  status_ = s;
  has_status_ = true;
  ++status_serial_;
  ++stats_.statuses;
  bool progress = false;
  while (!unacked_.empty() && unacked_.front().seq < s.ack_seq) {
    unacked_bytes_ -= unacked_.front().bytes.size();
    unacked_.pop_front();
    progress = true;
  }
  if (progress) last_progress_ = Clock::now();
  if (s.naks > naks_seen_) {
    naks_seen_ = s.naks;
    ++stats_.naks_seen;
    // Go back N: the printer dropped everything after the bad frame.
    (void)resend_unacked();
  }
}

Status HostLink::check_timers() {
  if (unacked_.empty()) return {};
  const auto now = Clock::now();
  if (now - last_progress_ > options_.dead_link_timeout)
    return fail(ErrorCode::kTimeout,
                transport_.describe() + ": printer acknowledged nothing for " +
                    std::to_string(options_.dead_link_timeout.count()) + " ms (waiting for frame seq " +
                    std::to_string(unacked_.front().seq) + ")");
  if (now - last_progress_ > options_.retransmit_timeout && now - last_resend_ > options_.retransmit_timeout) {
    ++stats_.timeouts;
    return resend_unacked();
  }
  return {};
}

Status HostLink::poll(milliseconds timeout) {
  if (auto s = read_available(timeout); !s) return s;
  return check_timers();
}

Status HostLink::drain(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!unacked_.empty()) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    if (left.count() <= 0)
      return fail(ErrorCode::kTimeout, transport_.describe() + ": " + std::to_string(unacked_.size()) +
                                           " frames still unacknowledged after " +
                                           std::to_string(timeout.count()) + " ms");
    if (auto s = poll(std::min(left, milliseconds(20))); !s) return s;
  }
  return {};
}

Result<StatusMsg> HostLink::query_status(milliseconds timeout) {
  const std::uint32_t query_seq = next_seq_;
  if (auto s = send(MessageType::kStatusQuery, {}); !s) return fail(s.error());
  const auto deadline = Clock::now() + timeout;
  while (!(has_status_ && status_.ack_seq > query_seq)) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    if (left.count() <= 0)
      return fail(ErrorCode::kTimeout, transport_.describe() + ": no status within " +
                                           std::to_string(timeout.count()) + " ms of asking");
    if (auto s = poll(std::min(left, milliseconds(20))); !s) return fail(s.error());
  }
  return status_;
}

std::optional<RejectMsg> HostLink::take_reject() {
  auto r = std::move(reject_);
  reject_.reset();
  return r;
}

std::optional<JobReportMsg> HostLink::take_report() {
  auto r = std::move(report_);
  report_.reset();
  return r;
}

}  // namespace tp::device
