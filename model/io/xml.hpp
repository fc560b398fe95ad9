// A small, strict XML reader (no XML library is among the dependencies), enough for Jerboa .jme
// files and similar tool output.
//
// Supported: the XML declaration and processing instructions (skipped), comments, one root
// element, nested elements, attributes in single or double quotes, character data, CDATA sections,
// the five predefined entities (&lt; &gt; &amp; &quot; &apos;) and character references (&#65;
// &#x41;). A DOCTYPE declaration without an internal subset is skipped.
// Rejected, as Error(Parse) located "<source>:<line>" (or "line <n>"): mismatched or unclosed tags,
// duplicate attributes, unquoted attribute values, `<` in attribute values, unknown entities,
// non-whitespace text outside the root, a second root, unterminated comments/CDATA.
// Namespaces are not interpreted (a prefixed name is just a name).
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gmr::io {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // document order
  std::vector<std::unique_ptr<XmlElement>> children;
  std::string text;  // all character data directly inside the element (CDATA included), decoded
  size_t line = 0;   // line of the start tag

  const std::string* attribute(std::string_view key) const;
  const XmlElement* child(std::string_view name) const;  // first child with that name
  std::vector<const XmlElement*> children_named(std::string_view name) const;
};

XmlElement parse_xml(std::string_view text, const std::string& source = {});

}  // namespace gmr::io
