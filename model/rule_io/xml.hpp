// XML documents for Jerboa .jme files and similar tool output, parsed by tinyxml2
// (https://leethomason.github.io/tinyxml2/), with located errors.
//
// tinyxml2 reads the XML declaration, processing instructions, comments, elements, attributes in
// single or double quotes, character data, CDATA sections, the five predefined entities (&lt; &gt;
// &amp; &quot; &apos;) and character references (&#65; &#x41;). Namespaces are not interpreted (a
// prefixed name is just a name); a DOCTYPE is kept as an unknown node (one with an internal subset
// ends at its first '>', leaving text outside the root element).
//
// Rejected, as Error(Parse) "malformed XML: ..." located "<source>:<line>" (or "line <n>"):
//  * by tinyxml2: end tags that do not match (located at the start tag left open), elements not
//    closed, duplicate attributes, unquoted attribute values, unterminated comments and CDATA
//    sections, an empty document, and elements nested about TINYXML2_MAX_ELEMENT_DEPTH deep (100
//    levels in tinyxml2 9, 500 from 10; the limit keeps the recursive parser within the stack);
//  * by XmlDocument on top of tinyxml2, which leaves these out (XML 1.0: §2.1 one root element,
//    §2.3 AttValue without '<', §4.1 references): a second root element, non-whitespace text
//    outside the root, '<' in an attribute value, '&' that does not start a reference, an entity
//    reference other than the five predefined ones (§4.6; tinyxml2 would keep it verbatim), a
//    character reference to 0, a surrogate or beyond U+10FFFF. The references are checked on a
//    second parse that keeps them verbatim, so the text is parsed twice.
// Not rejected (tinyxml2 accepts them): "--" inside a comment, attributes without whitespace
// between them (<a x='1'y='2'/>).
#pragma once
#include <tinyxml2.h>

#include <string>
#include <string_view>
#include <vector>

namespace gmr::io {

class XmlDocument {
 public:
  // Parses `text` (copied); `source` names it in error locations. Throws Error(Parse).
  explicit XmlDocument(std::string_view text, std::string source = {});
  XmlDocument(const XmlDocument&) = delete;
  XmlDocument& operator=(const XmlDocument&) = delete;

  const tinyxml2::XMLElement& root() const { return *doc_.RootElement(); }
  // "<source>:<line>" (or "line <n>") of a node: the line of its start tag for an element.
  std::string at(const tinyxml2::XMLNode& n) const { return at_line(n.GetLineNum()); }
  std::string at_line(int line) const;

 private:
  tinyxml2::XMLDocument doc_;
  std::string source_;
};

// The child elements of `e` named `name` (every child element when `name` is null), in document
// order.
std::vector<const tinyxml2::XMLElement*> xml_children(const tinyxml2::XMLElement& e,
                                                      const char* name = nullptr);

// All character data directly inside `e` (CDATA sections included), references decoded.
std::string xml_text(const tinyxml2::XMLElement& e);

}  // namespace gmr::io
