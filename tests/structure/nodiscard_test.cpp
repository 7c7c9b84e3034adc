// tests/structure/nodiscard_test.cpp: every function a header declares returning Result<...> or
// Status is [[nodiscard]], so a dropped error is a compiler warning (Abseil's MUST_USE_RESULT).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/paths.h"

namespace tp {
namespace {

namespace fs = std::filesystem;

// A declaration line: optional specifiers, the result type, a name and its opening parenthesis.
const std::regex kDeclaration(
    R"(^\s*(?:(?:static|inline|virtual|constexpr|friend|explicit)\s+)*(?:[\w:]+::)?(?:Result<.*>|Status)\s+~?[\w:]+\s*\()");

// "file:line: text" for every such declaration without [[nodiscard]] on its line or the line before.
std::vector<std::string> missing_nodiscard(const fs::path& root) {
  std::vector<std::string> missing;
  for (const char* layer : {"device", "geometry", "rip", "drivers", "simulator", "host"}) {
    if (!fs::exists(root / layer)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root / layer)) {
      if (!e.is_regular_file() || e.path().extension() != ".h") continue;
      std::ifstream in(e.path());
      std::string line, prev;
      for (int n = 1; std::getline(in, line); ++n, prev = line) {
        if (!std::regex_search(line, kDeclaration) || line.find("return ") != std::string::npos) continue;
        const bool marked =
            line.find("[[nodiscard]]") != std::string::npos || prev.find("[[nodiscard]]") != std::string::npos;
        if (!marked) missing.push_back(fs::relative(e.path(), root).string() + ":" + std::to_string(n) + ": " + line);
      }
    }
  }
  return missing;
}

TEST(Structure, FunctionsReturningResultOrStatusAreNodiscard) {
  const auto missing = missing_nodiscard(test::source_dir());
  std::string list;
  for (const auto& m : missing) list += "  " + m + "\n";
  EXPECT_TRUE(missing.empty()) << missing.size() << " declarations lack [[nodiscard]]:\n" << list;
}

TEST(Structure, TheScanFindsAnUnmarkedDeclaration) {
  // The scanner itself: it must see the shapes the tree uses, and accept the marked ones.
  EXPECT_TRUE(std::regex_search("  static Result<std::unique_ptr<X>> open(const C& c);", kDeclaration));
  EXPECT_TRUE(std::regex_search("  virtual device::Status write(std::span<const std::uint8_t> b) = 0;", kDeclaration));
  EXPECT_TRUE(std::regex_search("Status validate(const Job& job);", kDeclaration));
  EXPECT_FALSE(std::regex_search("  Status status_;", kDeclaration));
  EXPECT_FALSE(std::regex_search("bool ok(const Status& s);", kDeclaration));
}

}  // namespace
}  // namespace tp
