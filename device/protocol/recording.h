// device/protocol/recording.h: recording a link's traffic to a file, and reading recordings back
// (for `printctl wire-dump` and golden tests).
//
// File: 8-byte magic "TPWIRE01", then records: u8 kind, u64 microseconds since the recording
// began, u32 length, `length` bytes. Kinds: 0 host->printer bytes, 1 printer->host bytes,
// 2 event text (reset, reconnect, disconnect).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "device/protocol/transport.h"

namespace tp::device {

enum class RecordKind : std::uint8_t { kHostToPrinter = 0, kPrinterToHost = 1, kEvent = 2 };

struct WireRecord {
  RecordKind kind = RecordKind::kEvent;
  std::uint64_t time_us = 0;
  std::vector<std::uint8_t> bytes;
};

/// Wraps another transport and appends everything that crosses it to a recording file.
class RecordingTransport final : public Transport {
 public:
  /// Creates (truncates) `path`. Fails with kInvalidArgument if it cannot be written.
  [[nodiscard]] static Result<std::unique_ptr<RecordingTransport>> create(Transport& inner,
                                                                          const std::filesystem::path& path);

  [[nodiscard]] Status write(std::span<const std::uint8_t> bytes) override;
  [[nodiscard]] Result<std::size_t> read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
  [[nodiscard]] Status reset() override;
  [[nodiscard]] Status reconnect(std::chrono::milliseconds timeout) override;
  std::string describe() const override;

 private:
  RecordingTransport(Transport& inner, std::ofstream out);
  void record(RecordKind kind, std::span<const std::uint8_t> bytes);

  Transport& inner_;
  std::mutex mutex_;
  std::ofstream out_;
  std::chrono::steady_clock::time_point start_;
};

/// Reads a whole recording. Fails with kMalformedFrame naming the file and record number if the
/// magic is wrong or a record is truncated.
[[nodiscard]] Result<std::vector<WireRecord>> read_recording(const std::filesystem::path& path);

/// Same, from bytes in memory (`name` appears in errors).
[[nodiscard]] Result<std::vector<WireRecord>> parse_recording(std::span<const std::uint8_t> bytes,
                                                              const std::string& name);

}  // namespace tp::device
