// host/common/failure_report.cpp: placeholder and fallback report.json.
#include "host/common/failure_report.h"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "host/common/atomic_file.h"
#include "host/common/text.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Rewrites the file in place (no temporary: on a full disk only the reserved blocks are left).
Status overwrite_in_place(const fs::path& path, std::string text) {
  if (text.size() < kReservedReportBytes) text.append(kReservedReportBytes - text.size() - 1, ' ').push_back('\n');
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return fail(ErrorCode::kIo, path.string() + ": cannot write: " + errno_text(errno));
  size_t off = 0;
  int e = 0;
  while (off < text.size()) {
    ssize_t n = ::pwrite(fd, text.data() + off, text.size() - off, static_cast<off_t>(off));
    if (n < 0) {
      if (errno == EINTR) continue;
      e = errno;
      break;
    }
    off += static_cast<size_t>(n);
  }
  if (e == 0 && ::ftruncate(fd, static_cast<off_t>(text.size())) != 0) e = errno;
  if (e == 0 && ::fsync(fd) != 0) e = errno;
  ::close(fd);
  if (e != 0) return fail(ErrorCode::kIo, path.string() + ": " + errno_text(e));
  return {};
}

}  // namespace

Status reserve_report(const fs::path& out_dir, const std::string& job_name, std::int64_t job_id) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) return fail(ErrorCode::kIo, out_dir.string() + ": " + ec.message());
  json j = {{"job", printable_utf8(job_name)}, {"job_id", job_id}, {"state", "running"}};
  return overwrite_in_place(out_dir / "report.json", dump_json(j, 2) + "\n");
}

Status ensure_failure_report(const fs::path& out_dir, const std::string& job_name, std::int64_t job_id,
                             const std::string& state, const std::string& error) {
  const fs::path path = out_dir / "report.json";
  {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    json j = json::parse(ss.str(), nullptr, false);
    if (!j.is_discarded() && j.is_object() && j.value("state", "") == state && j.contains("error")) return {};
  }
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  json j = {{"job", printable_utf8(job_name)}, {"job_id", job_id}, {"state", state}, {"error", printable_utf8(error)}};
  std::string text = dump_json(j, 2) + "\n";
  if (text.size() >= kReservedReportBytes) {
    j["error"] = printable_utf8(error.substr(0, kReservedReportBytes / 2)) + "...";
    text = dump_json(j, 2) + "\n";
  }
  return overwrite_in_place(path, text);
}

}  // namespace tp::host
