// tests/support/paths.cpp: locating test inputs and a per-test scratch directory.
#include "tests/support/paths.h"

#include <cstdlib>
#include <unistd.h>

namespace tp::test {

namespace {
std::filesystem::path from_env(const char* var, const char* fallback) {
  const char* v = std::getenv(var);
  return std::filesystem::path(v && *v ? v : fallback);
}
}  // namespace

std::filesystem::path shared_data_dir() { return from_env("TP_SHARED_DATA", TP_DEFAULT_SHARED_DATA); }
std::filesystem::path source_dir() { return from_env("TP_SOURCE_DIR", TP_DEFAULT_SOURCE_DIR); }
std::filesystem::path bin_dir() { return from_env("TP_BIN_DIR", TP_DEFAULT_BIN_DIR); }

std::filesystem::path scratch_dir(const std::string& name) {
  // One tree per process so tests running in parallel under ctest never share a folder.
  auto dir = std::filesystem::temp_directory_path() /
             ("tp-test-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tp::test
