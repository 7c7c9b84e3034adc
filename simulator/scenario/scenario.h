// simulator/scenario/scenario.h: fault-injection scenarios for printsim (JSON): which fault,
// when it strikes (swath, frame on the wire, or time), and for how long. The format is in
// docs/simulator.md; "expect" and "job" objects are allowed and left to test runners.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "simulator/common/error.h"

namespace tp::sim {

enum class FaultType : std::uint8_t {
  kStall,           ///< bulk OUT endpoint halts (link)
  kDropFrame,       ///< frames vanish on the wire (link)
  kCorruptCrc,      ///< a bit flips in frames on the wire (link)
  kUnplug,          ///< the USB cable is pulled, then plugged back after duration_ms
  kInkLow,          ///< printer pauses for duration_ms
  kCoverOpen,
  kMediaOut,
  kMediaJam,        ///< printer faults; the job cannot finish
  kHeadStrike,
  kCutterNotReady,  ///< cutter-ready input drops for duration_ms
  kEmergencyStop,   ///< emergency-stop input asserts (and the printer stops)
  kPowerLoss,       ///< the printer loses power: job and buffer gone, USB away for duration_ms
  kBufferClear,     ///< the operator clears the printer: job and buffer gone, link stays
};

std::string_view to_string(FaultType type);

struct FaultSpec {
  FaultType type = FaultType::kStall;
  /// Trigger, exactly one: when swath N's header arrives (link faults) or N is about to print
  /// (printer and cutter faults); the Nth frame on the wire (1-based); or ms after the first job began.
  std::optional<std::uint32_t> at_swath;
  std::optional<std::uint64_t> at_frame;
  std::optional<std::int64_t> after_ms;
  std::int64_t duration_ms = 0;  ///< unplug, pauses, cutter not ready, e-stop (0: stays)
  std::uint32_t count = 1;       ///< consecutive frames for drop_frame and corrupt_crc
};

struct Scenario {
  std::string description;
  std::vector<FaultSpec> faults;
};

/// Parses scenario JSON. Errors name the source and the JSON pointer of the bad field
/// ("jam.json: /faults/1/type: unknown fault 'jammed'").
[[nodiscard]] Result<Scenario> parse_scenario(std::string_view text, std::string_view source);
/// Reads and parses a scenario file.
[[nodiscard]] Result<Scenario> load_scenario(const std::filesystem::path& path);

}  // namespace tp::sim
