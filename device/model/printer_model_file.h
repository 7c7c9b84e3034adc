// device/model/printer_model_file.h: the printer model description file (".tpm"), so a job can
// name a printer other than the built-in one. Format: docs/protocol.md, "Printer model files".
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "device/common/error.h"
#include "device/model/printer_model.h"

namespace tp::device {

/// Parses a model description. `source` names the text in errors ("lab.tpm:7: key 'dpi_x':
/// expected an integer in 50..4800, got 'fast'"). Fails with kParse on a missing header line,
/// unknown or repeated key, malformed or out-of-range value, or a model that fails validate().
[[nodiscard]] Result<PrinterModel> parse_printer_model(std::string_view text, std::string_view source);

/// Reads and parses a model file; kParse errors name the path, kInvalidArgument if unreadable.
[[nodiscard]] Result<PrinterModel> load_printer_model(const std::filesystem::path& path);

/// Writes `model` in the file format; parse_printer_model(format_printer_model(m)) == m.
std::string format_printer_model(const PrinterModel& model);

/// Checks the model's internal consistency (inks present, resolutions, sizes, speeds), naming
/// the offending field.
[[nodiscard]] Status validate_printer_model(const PrinterModel& model);

}  // namespace tp::device
