#include "model/rule_io/xml.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <utility>

#include "model/core/error.hpp"

namespace gmr::io {

namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;
using tinyxml2::XMLText;

// What went wrong, in words, for tinyxml2's error codes.
std::string describe(const tinyxml2::XMLDocument& d) {
  std::string what;
  switch (d.ErrorID()) {
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      what = "bad element tag";
      break;
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      what = "bad attribute (unquoted value, duplicate name or missing '=')";
      break;
    case tinyxml2::XML_ERROR_PARSING_TEXT:
      what = "text not followed by a tag (after the root element?)";
      break;
    case tinyxml2::XML_ERROR_PARSING_CDATA:
      what = "unterminated CDATA section";
      break;
    case tinyxml2::XML_ERROR_PARSING_COMMENT:
      what = "unterminated comment";
      break;
    case tinyxml2::XML_ERROR_PARSING_DECLARATION:
      what = "bad XML declaration";
      break;
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
      what = "bad <!...> declaration";
      break;
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
      what = "no root element";
      break;
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      what = "element closed by a different end tag";
      break;
    case tinyxml2::XML_ERROR_PARSING:
      what = "element not closed, or a tag that cannot be read";
      break;
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
      what = "elements nested too deeply (tinyxml2's limit: " +
             std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) + " levels)";
      break;
    default:
      what = d.ErrorName();
      break;
  }
  // ErrorStr() is "Error=... ErrorID=... Line number=<n>[: <detail>]"; keep the detail.
  const std::string_view s = d.ErrorStr();
  const size_t ln = s.find("Line number=");
  const size_t colon = ln == std::string_view::npos ? ln : s.find(": ", ln);
  if (colon != std::string_view::npos) what += " (" + std::string(s.substr(colon + 2)) + ")";
  return what;
}

bool predefined_entity(std::string_view name) {
  return name == "lt" || name == "gt" || name == "amp" || name == "quot" || name == "apos";
}

// The first reference in the undecoded character data `raw` that is not one of XML 1.0's (§4.1
// character references to a Unicode scalar value other than 0, §4.6 the predefined entities):
// its offset and a message.
std::optional<std::pair<size_t, std::string>> bad_reference(std::string_view raw) {
  for (size_t p = raw.find('&'); p != std::string_view::npos; p = raw.find('&', p + 1)) {
    const size_t e = raw.find(';', p);
    const std::string_view ref = raw.substr(p + 1, e == std::string_view::npos ? 0 : e - p - 1);
    const bool word = !ref.empty() && std::all_of(ref.begin(), ref.end(), [](char c) {
      return c == '#' || std::isalnum(static_cast<unsigned char>(c));
    });
    if (e == std::string_view::npos || !word)
      return std::pair{p, std::string("'&' that does not start a reference")};
    if (predefined_entity(ref)) continue;
    if (ref[0] != '#') return std::pair{p, "unknown entity &" + std::string(ref) + ";"};
    const bool hex = ref.size() > 1 && (ref[1] == 'x' || ref[1] == 'X');
    const std::string_view digits = ref.substr(hex ? 2 : 1);
    unsigned long cp = 0;
    const auto [end, ec] =
        std::from_chars(digits.data(), digits.data() + digits.size(), cp, hex ? 16 : 10);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || cp == 0 ||
        cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
      return std::pair{p, "bad character reference &" + std::string(ref) + ";"};
  }
  return std::nullopt;
}

// Line breaks in s[from, to).
int newlines(std::string_view s, size_t from, size_t to) {
  return static_cast<int>(std::count(s.begin() + static_cast<std::ptrdiff_t>(from),
                                     s.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
}

// The checks of the header that tinyxml2 leaves out, on the document parsed with references kept
// verbatim (`raw`). Iterative: the depth is bounded by tinyxml2's limit, but a stack costs nothing.
void check_raw(const XmlDocument& where, const tinyxml2::XMLDocument& raw) {
  auto fail = [&](int line, const std::string& what) {
    throw Error(ErrorCode::Parse, "malformed XML: " + what, where.at_line(line));
  };
  const XMLElement* root = nullptr;
  for (const XMLNode* n = raw.FirstChild(); n; n = n->NextSibling()) {
    if (const XMLElement* e = n->ToElement()) {
      if (root) fail(e->GetLineNum(), "a second root element <" + std::string(e->Name()) + ">");
      root = e;
    } else if (n->ToText()) {
      fail(n->GetLineNum(), "text outside the root element");
    }
  }
  if (!root) fail(1, "no root element");
  // Nodes in document order (pre-order).
  std::vector<const XMLNode*> todo{root};
  while (!todo.empty()) {
    const XMLNode* n = todo.back();
    todo.pop_back();
    if (const XMLElement* e = n->ToElement()) {
      for (const XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
        const std::string_view v = a->Value();
        if (const size_t lt = v.find('<'); lt != std::string_view::npos)
          fail(a->GetLineNum() + newlines(v, 0, lt),
               "'<' in the value of attribute " + std::string(a->Name()));
        if (auto bad = bad_reference(v))
          fail(a->GetLineNum() + newlines(v, 0, bad->first),
               bad->second + " in attribute " + a->Name());
      }
      for (const XMLNode* c = e->LastChild(); c; c = c->PreviousSibling()) todo.push_back(c);
    } else if (const XMLText* t = n->ToText(); t && !t->CData()) {
      // The node's line is that of its first non-whitespace character.
      const std::string_view v = t->Value();
      if (auto bad = bad_reference(v))
        fail(t->GetLineNum() + newlines(v, v.find_first_not_of(" \t\r\n"), bad->first),
             bad->second);
    }
  }
}

}  // namespace

XmlDocument::XmlDocument(std::string_view text, std::string source)
    : doc_(true, tinyxml2::PRESERVE_WHITESPACE), source_(std::move(source)) {
  doc_.Parse(text.data(), text.size());
  if (doc_.Error())
    throw Error(ErrorCode::Parse, "malformed XML: " + describe(doc_),
                at_line(std::max(doc_.ErrorLineNum(), 1)));
  tinyxml2::XMLDocument raw(false, tinyxml2::PRESERVE_WHITESPACE);
  raw.Parse(text.data(), text.size());
  check_raw(*this, raw);
}

std::string XmlDocument::at_line(int line) const {
  return source_.empty() ? "line " + std::to_string(line) : source_ + ":" + std::to_string(line);
}

std::vector<const XMLElement*> xml_children(const XMLElement& e, const char* name) {
  std::vector<const XMLElement*> out;
  for (const XMLElement* c = e.FirstChildElement(name); c; c = c->NextSiblingElement(name))
    out.push_back(c);
  return out;
}

std::string xml_text(const XMLElement& e) {
  std::string out;
  for (const XMLNode* n = e.FirstChild(); n; n = n->NextSibling())
    if (const XMLText* t = n->ToText()) out += t->Value();
  return out;
}

}  // namespace gmr::io
