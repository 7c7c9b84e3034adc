// geometry/pattern/xml_tokenizer.cpp: tolerant XML tokenizing and entity decoding.
#include "geometry/pattern/import/xml_tokenizer.h"

#include <algorithm>
#include <cctype>

namespace tp::geometry {
namespace {

bool is_name_start(char c) {
  unsigned char u = static_cast<unsigned char>(c);
  return std::isalpha(u) || c == '_' || c == ':' || u >= 0x80;
}

bool is_name_char(char c) {
  unsigned char u = static_cast<unsigned char>(c);
  return is_name_start(c) || std::isdigit(u) || c == '-' || c == '.';
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// UTF-8 encoding of a code point (invalid ones become U+FFFD).
void append_utf8(std::string& out, unsigned long cp) {
  if (cp == 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = 0xFFFD;
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

}  // namespace

std::string decode_xml_entities(std::string_view t) {
  std::string out;
  out.reserve(t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] != '&') {
      out += t[i];
      continue;
    }
    size_t semi = t.find(';', i + 1);
    // Entities are short; a far ';' means this '&' is just a character.
    if (semi == std::string_view::npos || semi - i > 12) {
      out += '&';
      continue;
    }
    std::string_view ent = t.substr(i + 1, semi - i - 1);
    bool ok = true;
    if (ent == "lt") out += '<';
    else if (ent == "gt") out += '>';
    else if (ent == "amp") out += '&';
    else if (ent == "quot") out += '"';
    else if (ent == "apos") out += '\'';
    else if (ent.size() >= 2 && ent[0] == '#') {
      bool hex = ent[1] == 'x' || ent[1] == 'X';
      std::string_view digits = ent.substr(hex ? 2 : 1);
      unsigned long cp = 0;
      ok = !digits.empty();
      for (char c : digits) {
        int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                : (hex && std::isxdigit(static_cast<unsigned char>(c))) ? std::tolower(c) - 'a' + 10
                                                                         : -1;
        if (d < 0) { ok = false; break; }
        cp = cp * (hex ? 16 : 10) + static_cast<unsigned long>(d);
        if (cp > 0x10FFFF) cp = 0x110000;  // saturate; becomes U+FFFD
      }
      if (ok) append_utf8(out, cp);
    } else {
      ok = false;
    }
    if (!ok) {
      out += '&';
      continue;
    }
    i = semi;
  }
  return out;
}

const std::string* find_attribute(const XmlToken& token, std::string_view name) {
  for (const XmlAttribute& a : token.attributes)
    if (a.name == name) return &a.value;
  return nullptr;
}

void XmlTokenizer::advance(size_t n) {
  size_t end = std::min(s_.size(), pos_ + n);
  line_ += static_cast<int>(std::count(s_.begin() + static_cast<long>(pos_), s_.begin() + static_cast<long>(end), '\n'));
  pos_ = end;
}

void XmlTokenizer::skip_until(std::string_view terminator) {
  size_t at = s_.find(terminator, pos_);
  advance(at == std::string_view::npos ? s_.size() - pos_ : at - pos_ + terminator.size());
}

bool XmlTokenizer::next(XmlToken& token) {
  while (pos_ < s_.size()) {
    token = XmlToken{};
    token.line = line_;
    if (s_[pos_] != '<') {
      // Character data up to the next '<' that can start markup.
      size_t start = pos_;
      size_t at = pos_;
      while (true) {
        at = s_.find('<', at);
        if (at == std::string_view::npos || at + 1 >= s_.size()) break;
        char c = s_[at + 1];
        if (is_name_start(c) || c == '/' || c == '!' || c == '?') break;
        ++at;
      }
      size_t end = at == std::string_view::npos ? s_.size() : at;
      advance(end - pos_);
      token.kind = XmlTokenKind::kText;
      token.text = decode_xml_entities(s_.substr(start, end - start));
      return true;
    }
    std::string_view rest = s_.substr(pos_);
    if (rest.starts_with("<!--")) {
      skip_until("-->");
      continue;
    }
    if (rest.starts_with("<![CDATA[")) {
      size_t start = pos_ + 9;
      size_t at = s_.find("]]>", start);
      size_t end = at == std::string_view::npos ? s_.size() : at;
      token.kind = XmlTokenKind::kText;
      token.text = std::string(s_.substr(start, end - start));
      advance(end - pos_ + (at == std::string_view::npos ? 0 : 3));
      return true;
    }
    if (rest.starts_with("<?")) {
      skip_until("?>");
      continue;
    }
    if (rest.starts_with("<!")) {
      // DOCTYPE and friends, with an internal subset in brackets.
      size_t depth = 0;
      size_t i = pos_ + 2;
      for (; i < s_.size(); ++i) {
        if (s_[i] == '[') ++depth;
        else if (s_[i] == ']' && depth > 0) --depth;
        else if (s_[i] == '>' && depth == 0) break;
      }
      advance(i + 1 - pos_);
      continue;
    }
    if (read_tag(token)) return true;
  }
  return false;
}

bool XmlTokenizer::read_tag(XmlToken& token) {
  advance(1);  // '<'
  bool end_tag = pos_ < s_.size() && s_[pos_] == '/';
  if (end_tag) advance(1);
  size_t name_start = pos_;
  while (pos_ < s_.size() && is_name_char(s_[pos_])) ++pos_;
  token.name = std::string(s_.substr(name_start, pos_ - name_start));
  token.kind = end_tag ? XmlTokenKind::kEndTag : XmlTokenKind::kStartTag;
  // Attributes until '>' or '/>'; anything unreadable is skipped one character at a time.
  while (pos_ < s_.size()) {
    char c = s_[pos_];
    if (is_space(c)) {
      advance(1);
      continue;
    }
    if (c == '>') {
      advance(1);
      return true;
    }
    if (c == '/' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '>') {
      token.self_closing = true;
      advance(2);
      return true;
    }
    if (!is_name_start(c)) {
      advance(1);
      continue;
    }
    size_t an = pos_;
    while (pos_ < s_.size() && is_name_char(s_[pos_])) ++pos_;
    XmlAttribute attr{std::string(s_.substr(an, pos_ - an)), ""};
    while (pos_ < s_.size() && is_space(s_[pos_])) advance(1);
    if (pos_ < s_.size() && s_[pos_] == '=') {
      advance(1);
      while (pos_ < s_.size() && is_space(s_[pos_])) advance(1);
      if (pos_ < s_.size() && (s_[pos_] == '"' || s_[pos_] == '\'')) {
        char q = s_[pos_];
        size_t vs = pos_ + 1;
        size_t ve = s_.find(q, vs);
        if (ve == std::string_view::npos) ve = s_.size();
        attr.value = decode_xml_entities(s_.substr(vs, ve - vs));
        advance(std::min(s_.size(), ve + 1) - pos_);
      } else {
        size_t vs = pos_;
        while (pos_ < s_.size() && !is_space(s_[pos_]) && s_[pos_] != '>') ++pos_;
        attr.value = decode_xml_entities(s_.substr(vs, pos_ - vs));
      }
    }
    if (!end_tag) token.attributes.push_back(std::move(attr));
  }
  return true;
}

}  // namespace tp::geometry
