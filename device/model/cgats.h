// device/model/cgats.h: CGATS.17 text files (ArgyllCMS .ti1/.ti2/.ti3, chart layouts): reading
// with errors that name file and line, and writing.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "device/common/error.h"

namespace tp::device {

/// One table of a CGATS file: its file-type line ("CTI3"), keywords, fields and rows.
struct CgatsTable {
  std::string type;                                        ///< first line's identifier
  std::vector<std::pair<std::string, std::string>> keywords;  ///< in file order, quotes removed
  std::vector<std::string> fields;                         ///< BEGIN_DATA_FORMAT .. END_DATA_FORMAT
  std::vector<std::vector<std::string>> rows;              ///< BEGIN_DATA .. END_DATA, one per set

  /// Index of `field`, or -1.
  int field(std::string_view name) const;
  /// Value of `keyword`, or empty.
  std::string keyword(std::string_view name) const;
};

/// Parses every table in `text`. Fails with kParse naming `source` and the line: a data row with
/// the wrong number of values, NUMBER_OF_SETS disagreeing with the rows, a missing
/// END_DATA(_FORMAT), no table at all, an unterminated quote.
[[nodiscard]] Result<std::vector<CgatsTable>> parse_cgats(std::string_view text, std::string_view source);
/// Reads and parses a file (at most 64 MiB); kInvalidArgument if it cannot be read.
[[nodiscard]] Result<std::vector<CgatsTable>> load_cgats(const std::filesystem::path& path);
/// Writes one table; fields and keyword values are written as given (string keywords quoted).
std::string format_cgats(const CgatsTable& table);

}  // namespace tp::device
