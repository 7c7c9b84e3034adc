// tests/fuzz/host_request_fuzz.cpp: the daemon's control-socket request handler never throws,
// never crashes and always answers one valid JSON object with "ok", whatever line a client sends.
// fuzz-sources: host/daemon/requests host/store host/common
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "host/daemon/requests/request_handler.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  using namespace tp::host;
  static JobStore* store = [] {
    const fs::path dir = fs::temp_directory_path() / ("tp-request-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto s = JobStore::open(dir / "jobs.db");
    if (!s) __builtin_trap();
    // Jobs whose text is not UTF-8, as hot-folder names and DXF errors can be.
    (void)s->enqueue("caf\xE9", "/spool/a", "/out/a", "hot-folder:caf\xE9");
    auto id = s->enqueue("b", "/spool/b", "/out/b", "socket", "hash");
    (void)s->set_state(*id, JobState::kFailed, "bad \xFF\xFE bytes");
    return new JobStore(std::move(*s));
  }();
  RequestHooks hooks;
  hooks.submit = [](const fs::path& p, bool) -> Result<nlohmann::json> {
    if (p.string().size() % 2) return fail(ErrorCode::kJob, p.string() + ": refused \xFF");
    return nlohmann::json{{"id", 1}, {"name", p.filename().string()}};
  };
  hooks.cancel_running = [](std::int64_t) {};
  hooks.cancelled_queued = [](std::int64_t) {};
  const std::string line(reinterpret_cast<const char*>(data), size);
  const std::string reply = handle_request(*store, line, hooks);
  auto j = nlohmann::json::parse(reply, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("ok") || !j["ok"].is_boolean()) __builtin_trap();
  return 0;
}
