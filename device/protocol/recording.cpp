// device/protocol/recording.cpp: the recording transport wrapper and recording reader.
#include "device/protocol/recording.h"

#include <cstring>
#include <iterator>

#include "device/protocol/internal/byte_io.h"

namespace tp::device {

namespace {
constexpr char kMagic[8] = {'T', 'P', 'W', 'I', 'R', 'E', '0', '1'};
constexpr std::size_t kRecordHeaderBytes = 1 + 8 + 4;
}  // namespace

Result<std::unique_ptr<RecordingTransport>> RecordingTransport::create(Transport& inner,
                                                                       const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return fail(ErrorCode::kInvalidArgument, path.string() + ": cannot create wire recording");
  out.write(kMagic, sizeof kMagic);
  return std::unique_ptr<RecordingTransport>(new RecordingTransport(inner, std::move(out)));
}

RecordingTransport::RecordingTransport(Transport& inner, std::ofstream out)
    : inner_(inner), out_(std::move(out)), start_(std::chrono::steady_clock::now()) {}

void RecordingTransport::record(RecordKind kind, std::span<const std::uint8_t> bytes) {
  std::vector<std::uint8_t> head;
  wire::ByteWriter w(head);
  w.u8(static_cast<std::uint8_t>(kind));
  w.u64(static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start_).count()));
  w.u32(static_cast<std::uint32_t>(bytes.size()));
  std::lock_guard lock(mutex_);
  out_.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
  out_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out_.flush();
}

Status RecordingTransport::write(std::span<const std::uint8_t> bytes) {
  record(RecordKind::kHostToPrinter, bytes);
  return inner_.write(bytes);
}

Result<std::size_t> RecordingTransport::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  auto n = inner_.read(buffer, timeout);
  if (n && *n > 0) record(RecordKind::kPrinterToHost, buffer.first(*n));
  if (!n) {
    const std::string text = "read failed: " + n.error().what();
    record(RecordKind::kEvent, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  }
  return n;
}

Status RecordingTransport::reset() {
  static constexpr std::string_view kText = "reset";
  record(RecordKind::kEvent, std::span(reinterpret_cast<const std::uint8_t*>(kText.data()), kText.size()));
  return inner_.reset();
}

Status RecordingTransport::reconnect(std::chrono::milliseconds timeout) {
  auto s = inner_.reconnect(timeout);
  const std::string text = s ? "reconnected" : "reconnect failed: " + s.error().what();
  record(RecordKind::kEvent, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  return s;
}

std::string RecordingTransport::describe() const { return inner_.describe() + " (recorded)"; }

Result<std::vector<WireRecord>> parse_recording(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    return fail(ErrorCode::kMalformedFrame, name + ": not a wire recording (magic 'TPWIRE01' missing)");
  std::vector<WireRecord> records;
  wire::ByteReader r(bytes.subspan(sizeof kMagic));
  while (r.remaining() > 0) {
    const std::string where = name + ": record " + std::to_string(records.size() + 1);
    if (r.remaining() < kRecordHeaderBytes)
      return fail(ErrorCode::kMalformedFrame, where + ": truncated header");
    WireRecord rec;
    const std::uint8_t kind = r.u8("kind");
    if (kind > 2) return fail(ErrorCode::kMalformedFrame, where + ": kind " + std::to_string(kind) + " unknown");
    rec.kind = static_cast<RecordKind>(kind);
    rec.time_us = r.u64("time_us");
    const std::uint32_t len = r.u32("length");
    auto data = r.bytes(len, "bytes");
    if (!r.ok())
      return fail(ErrorCode::kMalformedFrame, where + ": announces " + std::to_string(len) + " bytes, file ends first");
    rec.bytes.assign(data.begin(), data.end());
    records.push_back(std::move(rec));
  }
  return records;
}

Result<std::vector<WireRecord>> read_recording(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kInvalidArgument, path.string() + ": cannot open wire recording");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_recording(bytes, path.string());
}

}  // namespace tp::device
