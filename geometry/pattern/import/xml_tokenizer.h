// geometry/pattern/import/xml_tokenizer.h: a small tolerant XML tokenizer (enough for SVG pattern files).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tp::geometry {

/// One attribute; the value has its entities decoded.
struct XmlAttribute {
  std::string name;
  std::string value;
};

/// What a token is.
enum class XmlTokenKind { kStartTag, kEndTag, kText };

/// A start tag (with attributes; `self_closing` for <x/>), an end tag, or character data
/// (text and CDATA, entities decoded). Comments, processing instructions and DOCTYPE are skipped.
struct XmlToken {
  XmlTokenKind kind = XmlTokenKind::kText;
  std::string name;                      ///< tag name as written (with any prefix, "svg:path")
  std::vector<XmlAttribute> attributes;
  bool self_closing = false;
  std::string text;
  int line = 1;                          ///< 1-based line where the token starts
};

/// Splits XML into tokens without ever failing: malformed markup is read the way browsers read
/// it (unquoted or valueless attributes, stray '<' or '&' as text, unknown entities kept as
/// written, unterminated comments or tags ending the input). It does not check nesting; callers
/// keep their own element stack.
class XmlTokenizer {
 public:
  explicit XmlTokenizer(std::string_view text) : s_(text) {}

  /// The next token; false at the end of the input.
  bool next(XmlToken& token);

 private:
  bool read_tag(XmlToken& token);
  void skip_until(std::string_view terminator);
  void advance(size_t n);

  std::string_view s_;
  size_t pos_ = 0;
  int line_ = 1;
};

/// `value` of attribute `name` in `token`, or nullptr.
const std::string* find_attribute(const XmlToken& token, std::string_view name);

/// Decodes &lt; &gt; &amp; &quot; &apos; &#N; &#xH; (unknown or malformed entities stay as written).
std::string decode_xml_entities(std::string_view text);

}  // namespace tp::geometry
