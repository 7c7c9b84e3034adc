// tests/device/protocol/message_table_test.cpp: docs/protocol.md's message table lists exactly the
// messages of device/protocol/message_table.h, with their codes and directions; every message
// round-trips through its generated encoder and decoder.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "device/protocol/frame.h"
#include "device/protocol/messages.h"
#include "tests/support/paths.h"

namespace tp::device {
namespace {

struct DocRow {
  std::string name;
  std::string direction;
};

// Rows of the "## Messages" table: "| 0x17 pause, 0x18 resume | H>P | ... |" gives two entries.
std::map<int, DocRow> documented_messages() {
  std::ifstream in(test::source_dir() / "docs/protocol.md");
  EXPECT_TRUE(in) << "docs/protocol.md not found";
  std::map<int, DocRow> rows;
  std::string line;
  bool in_section = false;
  const std::regex row(R"(^\| *(0x[0-9a-f]{2} [a-z_]+(?:, *0x[0-9a-f]{2} [a-z_]+)*) *\| *([HP]>[HP]) *\|)");
  const std::regex entry(R"((0x[0-9a-f]{2}) ([a-z_]+))");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## Messages";
    std::smatch m;
    if (!in_section || !std::regex_search(line, m, row)) continue;
    const std::string cell = m[1], dir = m[2];
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), entry); it != std::sregex_iterator(); ++it) {
      const int code = std::stoi((*it)[1].str(), nullptr, 16);
      EXPECT_EQ(rows.count(code), 0u) << "docs/protocol.md lists code " << (*it)[1] << " twice";
      rows[code] = {(*it)[2].str(), dir};
    }
  }
  return rows;
}

TEST(MessageTable, DocsTableMatchesTheCode) {
  const auto docs = documented_messages();
  ASSERT_FALSE(docs.empty()) << "no message table under '## Messages' in docs/protocol.md";
  for (MessageType t : kAllMessageTypes) {
    const int code = static_cast<int>(t);
    auto it = docs.find(code);
    ASSERT_NE(it, docs.end()) << "docs/protocol.md lacks message " << to_string(t) << " (0x" << std::hex << code << ")";
    EXPECT_EQ(it->second.name, to_string(t)) << "code 0x" << std::hex << code;
    EXPECT_EQ(it->second.direction, code < 0x80 ? "H>P" : "P>H") << to_string(t);
  }
  EXPECT_EQ(docs.size(), std::size(kAllMessageTypes)) << "docs/protocol.md lists messages the code does not have";
}

TEST(MessageTable, EveryCodeIsAMessageTypeAndNoOther) {
  int known = 0;
  for (int v = 0; v < 256; ++v) known += is_message_type(static_cast<std::uint8_t>(v)) ? 1 : 0;
  EXPECT_EQ(known, static_cast<int>(std::size(kAllMessageTypes)));
}

TEST(MessageTable, PayloadlessMessagesEncodeEmptyAndRefuseBytes) {
  std::vector<std::uint8_t> p;
  encode(PauseMsg{}, p);
  encode(StatusQueryMsg{}, p);
  EXPECT_TRUE(p.empty());
  EXPECT_TRUE(decode_resume(p));
  const std::vector<std::uint8_t> extra{1, 2};
  auto r = decode_report_query(extra);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().message, "report_query: 2 unexpected trailing bytes");
}

}  // namespace
}  // namespace tp::device
