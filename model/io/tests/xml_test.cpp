// The strict XML reader.
#include <gtest/gtest.h>

#include "model/core/error.hpp"
#include "model/io/xml.hpp"

using namespace gmr;
using namespace gmr::io;

TEST(Xml, ElementsAttributesTextEntitiesCdata) {
  const char* t =
      "<?xml version=\"1.0\"?>\n<!-- head -->\n<a x=\"1\" y='&lt;&amp;&quot;&apos;&gt;'>\n"
      "  <b/><b k=\"v\">hi &#65;&#x42; <![CDATA[<raw> & stuff]]></b>\n  <!-- c -->\n  <c>line\ntwo</c>\n</a>\n";
  XmlElement a = parse_xml(t);
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.line, 3u);
  ASSERT_NE(a.attribute("y"), nullptr);
  EXPECT_EQ(*a.attribute("y"), "<&\"'>");
  EXPECT_EQ(a.children_named("b").size(), 2u);
  EXPECT_EQ(a.children_named("b")[1]->text, "hi AB <raw> & stuff");
  EXPECT_EQ(a.child("c")->text, "line\ntwo");
  EXPECT_EQ(a.child("c")->line, 6u);
  EXPECT_EQ(a.attribute("zz"), nullptr);
}

TEST(Xml, ErrorsWithLines) {
  auto loc = [](const char* t) {
    try {
      parse_xml(t, "f.xml");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::Parse);
      return e.location() + " " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(loc("<a>\n<b>\n</a>").substr(0, 7), "f.xml:3");
  EXPECT_NE(loc("<a>\n<b>\n</a>").find("does not match <b>"), std::string::npos);
  EXPECT_EQ(loc("<a>\n\n<b x=1/></a>").substr(0, 7), "f.xml:3");
  EXPECT_NE(loc("<a x='1' x='2'/>").find("duplicate attribute"), std::string::npos);
  EXPECT_NE(loc("<a>&nbsp;</a>").find("unknown entity"), std::string::npos);
  EXPECT_NE(loc("<a><!-- x </a>").find("unterminated comment"), std::string::npos);
  EXPECT_NE(loc("<a><![CDATA[ x </a>").find("unterminated CDATA"), std::string::npos);
  EXPECT_NE(loc("<a/><b/>").find("second root"), std::string::npos);
  EXPECT_NE(loc("text<a/>").find("outside the root"), std::string::npos);
  EXPECT_NE(loc("<a>\n\n").find("not closed"), std::string::npos);
  EXPECT_NE(loc("<a x='<'/>").find("'<'"), std::string::npos);
  EXPECT_NE(loc("").find("no root"), std::string::npos);
}
