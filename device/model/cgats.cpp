// device/model/cgats.cpp: a tokenising CGATS.17 reader and writer.
#include "device/model/cgats.h"

#include <fstream>
#include <sstream>

namespace tp::device {

namespace {

constexpr std::size_t kMaxCgatsBytes = 64u << 20;

// Splits a line into tokens; "quoted strings" stay one token without their quotes.
bool tokenize(std::string_view line, std::vector<std::string>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size() || line[i] == '#') break;
    if (line[i] == '"') {
      const std::size_t end = line.find('"', i + 1);
      if (end == std::string_view::npos) return false;
      out.emplace_back(line.substr(i + 1, end - i - 1));
      i = end + 1;
    } else {
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
      out.emplace_back(line.substr(i, j - i));
      i = j;
    }
  }
  return true;
}

bool is_number(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) return false;
  return true;
}

}  // namespace

int CgatsTable::field(std::string_view name) const {
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i] == name) return static_cast<int>(i);
  return -1;
}

std::string CgatsTable::keyword(std::string_view name) const {
  for (const auto& [k, v] : keywords)
    if (k == name) return v;
  return {};
}

Result<std::vector<CgatsTable>> parse_cgats(std::string_view text, std::string_view source) {
  const std::string src(source);
  std::vector<CgatsTable> tables;
  enum class Where { kHeader, kFormat, kData } where = Where::kHeader;
  CgatsTable* t = nullptr;
  long long expected_sets = -1;
  std::size_t line_no = 0, table_line = 0;
  std::vector<std::string> tok;
  auto at = [&](std::size_t n) { return src + ":" + std::to_string(n) + ": "; };
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    if (!tokenize(line, tok)) return fail(ErrorCode::kParse, at(line_no) + "unterminated quoted string");
    if (tok.empty()) continue;
    if (where == Where::kFormat) {
      if (tok[0] == "END_DATA_FORMAT") {
        where = Where::kHeader;
        continue;
      }
      for (auto& f : tok) t->fields.push_back(f);
      continue;
    }
    if (where == Where::kData) {
      if (tok[0] == "END_DATA") {
        if (expected_sets >= 0 && static_cast<long long>(t->rows.size()) != expected_sets)
          return fail(ErrorCode::kParse, at(line_no) + "NUMBER_OF_SETS says " + std::to_string(expected_sets) +
                                             " but the table has " + std::to_string(t->rows.size()) + " rows");
        where = Where::kHeader;
        t = nullptr;
        continue;
      }
      if (tok.size() != t->fields.size())
        return fail(ErrorCode::kParse, at(line_no) + "data row has " + std::to_string(tok.size()) + " values, the format has " +
                                           std::to_string(t->fields.size()) + " fields");
      t->rows.push_back(tok);
      continue;
    }
    // Header: a new table starts with its identifier on a line of its own.
    if (!t) {
      if (tok.size() != 1 || tok[0].find_first_of("=") != std::string::npos)
        return fail(ErrorCode::kParse, at(line_no) + "expected a CGATS file identifier (such as CTI3), got '" + std::string(line) + "'");
      tables.emplace_back();
      t = &tables.back();
      t->type = tok[0];
      expected_sets = -1;
      table_line = line_no;
      continue;
    }
    if (tok[0] == "BEGIN_DATA_FORMAT") {
      where = Where::kFormat;
    } else if (tok[0] == "BEGIN_DATA") {
      if (t->fields.empty()) return fail(ErrorCode::kParse, at(line_no) + "BEGIN_DATA before any BEGIN_DATA_FORMAT");
      where = Where::kData;
    } else if (tok[0] == "NUMBER_OF_SETS") {
      if (tok.size() != 2 || !is_number(tok[1])) return fail(ErrorCode::kParse, at(line_no) + "NUMBER_OF_SETS needs a count");
      expected_sets = std::stoll(tok[1]);
      t->keywords.emplace_back(tok[0], tok[1]);
    } else if (tok[0] == "KEYWORD") {
      // Declares a private keyword; nothing to keep.
    } else {
      std::string value;
      for (std::size_t i = 1; i < tok.size(); ++i) value += (i > 1 ? " " : "") + tok[i];
      t->keywords.emplace_back(tok[0], value);
    }
  }
  if (where == Where::kFormat) return fail(ErrorCode::kParse, src + ": BEGIN_DATA_FORMAT without END_DATA_FORMAT");
  if (where == Where::kData) return fail(ErrorCode::kParse, src + ": BEGIN_DATA without END_DATA (file truncated?)");
  if (tables.empty()) return fail(ErrorCode::kParse, src + ": no CGATS table (empty file?)");
  if (t && t->rows.empty() && t->fields.empty())
    return fail(ErrorCode::kParse, src + ":" + std::to_string(table_line) + ": table '" + t->type + "' has no data");
  return tables;
}

Result<std::vector<CgatsTable>> load_cgats(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kInvalidArgument, path.string() + ": cannot open");
  std::string text;
  text.resize(kMaxCgatsBytes + 1);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCgatsBytes) return fail(ErrorCode::kParse, path.string() + ": larger than 64 MiB");
  return parse_cgats(text, path.string());
}

std::string format_cgats(const CgatsTable& t) {
  std::ostringstream o;
  o << t.type << "\n\n";
  for (const auto& [k, v] : t.keywords) {
    if (k == "NUMBER_OF_FIELDS" || k == "NUMBER_OF_SETS") continue;
    // Keywords outside the standard's own set are declared first (strict readers insist).
    if (k != "ORIGINATOR" && k != "DESCRIPTOR" && k != "CREATED" && k != "MANUFACTURER" && k != "SERIAL" &&
        k != "MATERIAL" && k != "INSTRUMENTATION")
      o << "KEYWORD \"" << k << "\"\n";
    o << k << " " << (is_number(v) ? v : "\"" + v + "\"") << "\n";
  }
  o << "\nNUMBER_OF_FIELDS " << t.fields.size() << "\nBEGIN_DATA_FORMAT\n";
  for (std::size_t i = 0; i < t.fields.size(); ++i) o << (i ? " " : "") << t.fields[i];
  o << "\nEND_DATA_FORMAT\n\nNUMBER_OF_SETS " << t.rows.size() << "\nBEGIN_DATA\n";
  for (const auto& row : t.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) o << (i ? " " : "") << row[i];
    o << "\n";
  }
  o << "END_DATA\n";
  return o.str();
}

}  // namespace tp::device
