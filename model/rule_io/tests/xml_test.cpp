// XML documents read by tinyxml2 (model/rule_io/xml.hpp): content, and every malformed case
// rejected with its line.
#include "model/rule_io/xml.hpp"

#include <gtest/gtest.h>

#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::io;

TEST(Xml, ElementsAttributesTextEntitiesCdata) {
  const char* t =
      "<?xml version=\"1.0\"?>\n<!-- head -->\n<a x=\"1\" y='&lt;&amp;&quot;&apos;&gt;'>\n"
      "  <b/><b k=\"v\">hi &#65;&#x42; <![CDATA[<raw> & stuff]]></b>\n  <!-- c -->\n  "
      "<c>line\ntwo</c>\n</a>\n";
  const XmlDocument d(t);
  const tinyxml2::XMLElement& a = d.root();
  EXPECT_STREQ(a.Name(), "a");
  EXPECT_EQ(a.GetLineNum(), 3);
  EXPECT_EQ(d.at(a), "line 3");
  ASSERT_NE(a.Attribute("y"), nullptr);
  EXPECT_STREQ(a.Attribute("y"), "<&\"'>");
  ASSERT_EQ(xml_children(a, "b").size(), 2u);
  EXPECT_EQ(xml_children(a).size(), 3u);
  EXPECT_EQ(xml_text(*xml_children(a, "b")[1]), "hi AB <raw> & stuff");
  EXPECT_EQ(xml_text(*a.FirstChildElement("c")), "line\ntwo");
  EXPECT_EQ(a.FirstChildElement("c")->GetLineNum(), 6);
  EXPECT_EQ(a.Attribute("zz"), nullptr);
  // Text interrupted by a comment is still the element's text; a character reference to a
  // code point beyond ASCII is UTF-8.
  EXPECT_EQ(xml_text(XmlDocument("<a>x<!-- c -->y&#xE9;</a>").root()), "xy\xC3\xA9");
}

namespace {
std::string loc(const std::string& t) {
  try {
    XmlDocument d(t, "f.xml");
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Parse);
    return e.location() + " " + e.message();
  }
  return "no error";
}
}  // namespace

// The strictness cases: tinyxml2 rejects most itself; XmlDocument adds the one-root, text-outside
// and reference checks tinyxml2 leaves out.
TEST(Xml, ErrorsWithLines) {
  // tinyxml2 locates a mismatched end tag at the start tag it fails to close (<b>, line 2),
  // not at the end tag (</a>, line 3).
  EXPECT_EQ(loc("<a>\n<b>\n</a>").substr(0, 7), "f.xml:2");
  EXPECT_NE(loc("<a>\n<b>\n</a>").find("closed by a different end tag (XMLElement name=b)"),
            std::string::npos);
  EXPECT_EQ(loc("<a>\n\n<b x=1/></a>").substr(0, 7), "f.xml:3");
  EXPECT_NE(loc("<a>\n\n<b x=1/></a>").find("bad attribute"), std::string::npos);
  // Duplicate attribute: tinyxml2 reports it as any bad attribute.
  EXPECT_EQ(loc("<a>\n<b x='1' x='2'/></a>").substr(0, 21), "f.xml:2 malformed XML");
  EXPECT_NE(loc("<a x='1' x='2'/>").find("bad attribute"), std::string::npos);
  EXPECT_NE(loc("<a><!-- x </a>").find("unterminated comment"), std::string::npos);
  EXPECT_NE(loc("<a><![CDATA[ x </a>").find("unterminated CDATA"), std::string::npos);
  // Elements left open: located at the innermost start tag.
  EXPECT_EQ(loc("<r>\n<a>\n\n"),
            "f.xml:2 malformed XML: element not closed, or a tag that cannot be read");
  EXPECT_NE(loc("").find("no root"), std::string::npos);
  EXPECT_NE(loc(" \n<!-- only a comment -->\n").find("no root"), std::string::npos);
  // Checks tinyxml2 leaves out.
  EXPECT_EQ(loc("<a/>\n<b/>"), "f.xml:2 malformed XML: a second root element <b>");
  EXPECT_EQ(loc("\ntext<a/>"), "f.xml:2 malformed XML: text outside the root element");
  EXPECT_NE(loc("<a></a>text").find("after the root element"), std::string::npos);
  EXPECT_EQ(loc("<a x='<'/>"), "f.xml:1 malformed XML: '<' in the value of attribute x");
  EXPECT_EQ(loc("<a>\n  <b>x\n &nbsp;</b></a>"), "f.xml:3 malformed XML: unknown entity &nbsp;");
  EXPECT_EQ(loc("<a\n x='&foo;'/>"), "f.xml:2 malformed XML: unknown entity &foo; in attribute x");
  EXPECT_NE(loc("<a>&#1114112;</a>").find("bad character reference &#1114112;"), std::string::npos);
  EXPECT_NE(loc("<a>&#xD800;</a>").find("bad character reference"), std::string::npos);
  EXPECT_NE(loc("<a>&#xZ;</a>").find("bad character reference"), std::string::npos);
  EXPECT_NE(loc("<a>a & b</a>").find("'&' that does not start a reference"), std::string::npos);
  // Of these checks, the first failing one in document order.
  EXPECT_EQ(loc("<a>\n<b>\n<c x='&p;'/>\n</b>\n&q;</a>"),
            "f.xml:3 malformed XML: unknown entity &p; in attribute x");
  EXPECT_NE(loc("<!DOCTYPE a [ <!ENTITY e 'x'> ]><a/>").find("text outside the root"),
            std::string::npos);
  // A CDATA section is not decoded, so '&' in it is no reference.
  EXPECT_EQ(loc("<a><![CDATA[&nbsp; &]]></a>"), "no error");
}

// What tinyxml2 accepts where the XML 1.0 grammar does not (§2.5 "--" in comments, §3.1
// whitespace between attributes): not worth a check of our own for tool-written files.
TEST(Xml, LeniencyOfTinyxml2) {
  EXPECT_EQ(loc("<a><!-- a -- b --></a>"), "no error");
  EXPECT_EQ(loc("<a x='1'y='2'/>"), "no error");
}

// tinyxml2 parses recursively and stops at TINYXML2_MAX_ELEMENT_DEPTH: deep nesting is a located
// error, not a stack overflow.
TEST(Xml, DeepNestingIsALocatedError) {
  std::string deep = "<?xml version=\"1.0\"?>\n\n";
  for (int i = 0; i < 20000; ++i) deep += "<x>";
  for (int i = 0; i < 20000; ++i) deep += "</x>";
  EXPECT_EQ(loc(deep), "f.xml:3 malformed XML: elements nested too deeply (tinyxml2's limit: " +
                           std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) +
                           " levels) (Element nesting is too deep.)");
  // The document counts as a level, so a little less than the limit in elements.
  std::string ok;
  for (int i = 0; i < TINYXML2_MAX_ELEMENT_DEPTH - 10; ++i) ok += "<x>";
  for (int i = 0; i < TINYXML2_MAX_ELEMENT_DEPTH - 10; ++i) ok += "</x>";
  EXPECT_EQ(loc(ok), "no error");
}
