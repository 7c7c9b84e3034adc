// tests/fuzz/device_firmware_fuzz.cpp: the printer controller fed a hostile host. The input is a
// sequence of messages (type byte, length byte, payload) that are framed with valid sequence
// numbers and CRCs, so the fuzzer reaches the controller's message handling rather than stopping
// at the CRC. Invariants: no crash, credits never go negative, output frames always decode.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "device/firmware/controller.h"
#include "device/protocol/frame.h"
#include "device/protocol/messages.h"

namespace {

struct NullSink : tp::device::PrintSink {
  void job_started(const tp::device::JobBeginMsg&, bool) override {}
  void swath_printed(const tp::device::SwathHeader& h, std::span<const std::uint8_t> raw, std::int64_t) override {
    if (raw.size() != h.raw_bytes) std::abort();
  }
  void job_finished(const tp::device::JobReportMsg&) override {}
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tp::device;
  static const MessageType kTypes[] = {MessageType::kHello,      MessageType::kStatusQuery, MessageType::kReportQuery,
                                       MessageType::kJobBegin,   MessageType::kJobEnd,      MessageType::kSwathHeader,
                                       MessageType::kSwathData,  MessageType::kFeed,        MessageType::kCutterCue,
                                       MessageType::kCueDone,    MessageType::kPause,       MessageType::kResume,
                                       MessageType::kAbort,      MessageType::kStatus};
  PrinterModel model;
  model.nozzles_per_ink = 16;
  model.swath_buffer_slots = 3;
  model.swath_buffer_bytes = 1u << 16;
  NullSink sink;
  PrinterController printer(model, &sink);
  std::vector<std::uint8_t> stream;
  // Always open the link first so later messages are not all refused.
  std::vector<std::uint8_t> hello;
  encode(HelloMsg{}, hello);
  (void)encode_frame(MessageType::kHello, 0, hello, stream);
  std::uint32_t seq = 1;
  std::size_t at = 0;
  while (at + 2 <= size) {
    const MessageType type = kTypes[data[at] % (sizeof kTypes / sizeof kTypes[0])];
    const std::size_t len = std::min<std::size_t>(data[at + 1], size - at - 2);
    std::span<const std::uint8_t> payload(data + at + 2, len);
    at += 2 + len;
    // Odd type bytes above 0x80 get a wrong sequence number: the receiver must shrug it off.
    const std::uint32_t s = (data[at - 2 - len] & 0x80) ? seq + 5 : seq++;
    (void)encode_frame(type, s, payload, stream);
  }
  printer.receive(stream, 0);
  printer.advance(1000000);
  const StatusMsg st = printer.status();
  if (st.free_slots > model.swath_buffer_slots || st.free_bytes > model.swath_buffer_bytes) std::abort();
  if (st.printed_next > st.swath_next) std::abort();
  const std::vector<std::uint8_t> out = printer.transmit(1u << 20);
  FrameDecoder dec;
  dec.feed(out);
  while (auto r = dec.next())
    if (!*r) std::abort();
  return 0;
}
