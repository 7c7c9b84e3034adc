// geometry/pattern/internal/read_file.cpp: whole-file reads for the importers.
#include "geometry/pattern/internal/read_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tp::geometry::internal {

Result<std::string> read_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail(ErrorCode::kIo, path.string() + ": no such file");
  auto size = std::filesystem::file_size(path, ec);
  if (ec) return fail(ErrorCode::kIo, path.string() + ": " + ec.message());
  if (size > max_bytes)
    return fail(ErrorCode::kIo, path.string() + ": file is " + std::to_string(size) + " bytes, more than the " +
                                    std::to_string(max_bytes) + " accepted");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path.string() + ": cannot open: " + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return fail(ErrorCode::kIo, path.string() + ": read failed");
  return ss.str();
}

}  // namespace tp::geometry::internal
