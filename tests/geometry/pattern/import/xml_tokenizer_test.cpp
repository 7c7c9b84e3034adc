// tests/geometry/pattern/xml_tokenizer_test.cpp: the tolerant XML tokenizer on good, odd and broken markup.
#include "geometry/pattern/import/xml_tokenizer.h"

#include <gtest/gtest.h>

namespace tp::geometry {
namespace {

std::vector<XmlToken> all(std::string_view s) {
  std::vector<XmlToken> out;
  XmlTokenizer t(s);
  XmlToken tok;
  while (t.next(tok)) out.push_back(tok);
  return out;
}

TEST(XmlTokenizer, TagsAttributesTextAndLines) {
  auto t = all("<?xml version=\"1.0\"?>\n<!DOCTYPE svg [ <!ENTITY x \"y\"> ]>\n<svg a=\"1\" b='two'>\n<p/>hi &amp; bye</svg>");
  // "\n" after the declaration and after the DOCTYPE, <svg>, "\n", <p/>, text, </svg>.
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[1].kind, XmlTokenKind::kText);
  EXPECT_EQ(t[2].kind, XmlTokenKind::kStartTag);
  EXPECT_EQ(t[2].name, "svg");
  EXPECT_EQ(t[2].line, 3);
  ASSERT_EQ(t[2].attributes.size(), 2u);
  EXPECT_EQ(*find_attribute(t[2], "b"), "two");
  EXPECT_TRUE(t[4].self_closing);
  EXPECT_EQ(t[4].line, 4);
  EXPECT_EQ(t[5].text, "hi & bye");
  EXPECT_EQ(t[6].kind, XmlTokenKind::kEndTag);
}

TEST(XmlTokenizer, ToleratesWhatBrowsersTolerate) {
  auto t = all("<g id=a checked data-x = \"q&quot;\" >1 < 2 &bogus; &#65;&#x42;<![CDATA[<raw>]]><!-- x --></g");
  ASSERT_GE(t.size(), 3u);
  EXPECT_EQ(*find_attribute(t[0], "id"), "a");
  EXPECT_EQ(*find_attribute(t[0], "checked"), "");
  EXPECT_EQ(*find_attribute(t[0], "data-x"), "q\"");
  EXPECT_EQ(t[1].text, "1 < 2 &bogus; AB");
  EXPECT_EQ(t[2].text, "<raw>");
  EXPECT_EQ(t.back().kind, XmlTokenKind::kEndTag);
}

TEST(XmlTokenizer, TruncatedInputEndsCleanly) {
  for (std::string s : {"<svg a=\"", "<!-- never closed", "<![CDATA[ open", "<svg", "<", "&#", "<a b='x' c"}) {
    auto t = all(s);
    EXPECT_LE(t.size(), 2u) << s;
  }
}

TEST(XmlTokenizer, EntityDecoding) {
  EXPECT_EQ(decode_xml_entities("&lt;&gt;&amp;&apos;&quot;"), "<>&'\"");
  EXPECT_EQ(decode_xml_entities("&#8220;"), "\xE2\x80\x9C");
  EXPECT_EQ(decode_xml_entities("&#0;"), "\xEF\xBF\xBD");
  EXPECT_EQ(decode_xml_entities("&#xZZ; & &;"), "&#xZZ; & &;");
}

}  // namespace
}  // namespace tp::geometry
