// tests/support/files.h: reading a test's input and output files (text, JSON) in one place.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace tp::test {

/// The bytes of a file as a string; empty if it cannot be read (the assertions that follow say why).
std::string read_text(const std::filesystem::path& path);

/// A JSON file (a job, a report). Throws std::runtime_error naming the file if it cannot be read
/// or is not JSON, so the test fails with the file's name rather than a bare parse error.
nlohmann::json read_json(const std::filesystem::path& path);

/// A JSON file that may not exist yet or may be half written (a report being polled): null then.
nlohmann::json read_json_or_null(const std::filesystem::path& path);

}  // namespace tp::test
