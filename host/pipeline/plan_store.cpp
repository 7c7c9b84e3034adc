// host/pipeline/plan_store.cpp: the job's plan directory and its index (see internal/plan_store.h).
#include "host/pipeline/internal/plan_store.h"

#include "host/common/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tp::host::internal {

namespace fs = std::filesystem;

namespace {

constexpr const char* kIndexName = "plan.json";
constexpr const char* kFormat = "tp-plan/1";

}  // namespace

Result<std::string> PlanStore::read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path.string() + ": cannot read the stored plan");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return fail(ErrorCode::kIo, path.string() + ": read error");
  return ss.str();
}

Result<PlanStore> PlanStore::open(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return fail(ErrorCode::kIo, dir.string() + ": " + ec.message());
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
  PlanStore s;
  s.dir_ = dir;
  s.index_ = {{"format", kFormat}, {"steps", nlohmann::json::object()}};
  const fs::path index = dir / kIndexName;
  if (!fs::exists(index, ec)) return s;
  auto text = read(index);
  if (!text) return fail(text.error());
  auto j = nlohmann::json::parse(*text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("format") || j["format"] != kFormat || !j.contains("steps") ||
      !j["steps"].is_object())
    return fail(ErrorCode::kPipeline, index.string() + ": not a plan index (" + kFormat + ")");
  for (const auto& [step, e] : j["steps"].items())
    if (!e.is_object() || !e.contains("inputs") || !e["inputs"].is_string() || !e.contains("file") ||
        !e["file"].is_string())
      return fail(ErrorCode::kPipeline, index.string() + ": step '" + step + "' has no inputs hash or file");
  s.index_ = std::move(j);
  return s;
}

std::optional<fs::path> PlanStore::find(std::string_view step, std::string_view inputs_hash) const {
  const auto& steps = index_["steps"];
  auto it = steps.find(std::string(step));
  if (it == steps.end() || (*it)["inputs"].get<std::string>() != inputs_hash) return std::nullopt;
  const fs::path file = dir_ / (*it)["file"].get<std::string>();
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  return file;
}

Status PlanStore::save(std::string_view step, std::string_view inputs_hash, const std::string& file,
                       const std::string& bytes) {
  if (auto st = write_file_atomic(dir_ / file, bytes, 0600); !st) return st;
  index_["steps"][std::string(step)] = {{"inputs", std::string(inputs_hash)}, {"file", file}, {"bytes", bytes.size()}};
  return write_file_atomic(dir_ / kIndexName, index_.dump(2) + "\n", 0600);
}

}  // namespace tp::host::internal
