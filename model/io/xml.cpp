#include "model/io/xml.hpp"

#include <cctype>

#include "model/core/error.hpp"

namespace gmr::io {

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return &v;
  return nullptr;
}

const XmlElement* XmlElement::child(std::string_view n) const {
  for (const auto& c : children)
    if (c->name == n) return c.get();
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::children_named(std::string_view n) const {
  std::vector<const XmlElement*> out;
  for (const auto& c : children)
    if (c->name == n) out.push_back(c.get());
  return out;
}

namespace {

class Parser {
 public:
  Parser(std::string_view t, const std::string& source) : t_(t), source_(source) {}

  XmlElement document() {
    XmlElement root;
    bool have_root = false;
    for (;;) {
      skip_space();
      if (p_ >= t_.size()) break;
      if (starts("<?")) {
        skip_until("?>", "processing instruction");
      } else if (starts("<!--")) {
        comment();
      } else if (starts("<!DOCTYPE")) {
        doctype();
      } else if (starts("<")) {
        if (have_root) fail("a second root element");
        root = element();
        have_root = true;
      } else {
        fail("text outside the root element");
      }
    }
    if (!have_root) fail("no root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::Parse, "malformed XML: " + what,
                source_.empty() ? "line " + std::to_string(line_) : source_ + ":" + std::to_string(line_));
  }
  bool starts(std::string_view s) const { return t_.substr(p_, s.size()) == s; }
  void advance(size_t k) {
    for (size_t i = 0; i < k && p_ < t_.size(); ++i, ++p_)
      if (t_[p_] == '\n') ++line_;
  }
  void skip_space() {
    while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) advance(1);
  }
  void skip_until(std::string_view end, const char* what) {
    const size_t e = t_.find(end, p_);
    if (e == std::string_view::npos) fail(std::string("unterminated ") + what);
    advance(e + end.size() - p_);
  }
  void comment() {
    advance(4);
    const size_t e = t_.find("--", p_);
    if (e == std::string_view::npos) fail("unterminated comment");
    advance(e - p_);
    if (!starts("-->")) fail("\"--\" inside a comment");
    advance(3);
  }
  void doctype() {
    const size_t e = t_.find('>', p_);
    if (e == std::string_view::npos) fail("unterminated DOCTYPE");
    if (t_.substr(p_, e - p_).find('[') != std::string_view::npos) fail("DOCTYPE internal subsets are not supported");
    advance(e + 1 - p_);
  }
  static bool name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; }
  static bool name_char(char c) {
    return name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  }
  std::string name() {
    if (p_ >= t_.size() || !name_start(t_[p_])) fail("expected a name");
    const size_t b = p_;
    while (p_ < t_.size() && name_char(t_[p_])) advance(1);
    return std::string(t_.substr(b, p_ - b));
  }
  // Decodes an entity at p_ ('&'), appends it.
  void entity(std::string& out) {
    const size_t e = t_.find(';', p_);
    if (e == std::string_view::npos || e - p_ > 12) fail("unterminated entity reference");
    const std::string_view ent = t_.substr(p_ + 1, e - p_ - 1);
    if (ent == "lt") out += '<';
    else if (ent == "gt") out += '>';
    else if (ent == "amp") out += '&';
    else if (ent == "quot") out += '"';
    else if (ent == "apos") out += '\'';
    else if (!ent.empty() && ent[0] == '#') {
      unsigned long cp = 0;
      const bool hex = ent.size() > 1 && (ent[1] == 'x' || ent[1] == 'X');
      const std::string_view digits = ent.substr(hex ? 2 : 1);
      if (digits.empty()) fail("empty character reference");
      for (char c : digits) {
        int d;
        if (std::isdigit(static_cast<unsigned char>(c))) d = c - '0';
        else if (hex && std::isxdigit(static_cast<unsigned char>(c))) d = std::tolower(c) - 'a' + 10;
        else fail("bad character reference &" + std::string(ent) + ";");
        cp = cp * (hex ? 16 : 10) + static_cast<unsigned long>(d);
        if (cp > 0x10FFFF) fail("character reference out of range");
      }
      // UTF-8 encoding
      if (cp < 0x80) out += static_cast<char>(cp);
      else if (cp < 0x800) {
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
    } else {
      fail("unknown entity &" + std::string(ent) + ";");
    }
    advance(e + 1 - p_);
  }
  XmlElement element() {
    XmlElement el;
    el.line = line_;
    advance(1);  // '<'
    el.name = name();
    for (;;) {
      const size_t before = p_;
      skip_space();
      if (p_ >= t_.size()) fail("unterminated start tag <" + el.name + ">");
      if (starts("/>")) {
        advance(2);
        return el;
      }
      if (t_[p_] == '>') {
        advance(1);
        break;
      }
      if (p_ == before) fail("expected whitespace before an attribute in <" + el.name + ">");
      std::string key = name();
      skip_space();
      if (p_ >= t_.size() || t_[p_] != '=') fail("expected '=' after attribute " + key);
      advance(1);
      skip_space();
      if (p_ >= t_.size() || (t_[p_] != '"' && t_[p_] != '\'')) fail("attribute " + key + " value must be quoted");
      const char q = t_[p_];
      advance(1);
      std::string value;
      for (;;) {
        if (p_ >= t_.size()) fail("unterminated value of attribute " + key);
        const char c = t_[p_];
        if (c == q) break;
        if (c == '<') fail("'<' in the value of attribute " + key);
        if (c == '&') {
          entity(value);
        } else {
          value += c;
          advance(1);
        }
      }
      advance(1);
      if (el.attribute(key)) fail("duplicate attribute " + key + " in <" + el.name + ">");
      el.attributes.emplace_back(std::move(key), std::move(value));
    }
    // content
    for (;;) {
      if (p_ >= t_.size()) fail("element <" + el.name + "> (line " + std::to_string(el.line) + ") is not closed");
      if (starts("</")) {
        advance(2);
        const std::string close = name();
        skip_space();
        if (p_ >= t_.size() || t_[p_] != '>') fail("expected '>' in end tag </" + close + ">");
        advance(1);
        if (close != el.name)
          fail("end tag </" + close + "> does not match <" + el.name + "> of line " + std::to_string(el.line));
        return el;
      }
      if (starts("<!--")) {
        comment();
      } else if (starts("<![CDATA[")) {
        advance(9);
        const size_t e = t_.find("]]>", p_);
        if (e == std::string_view::npos) fail("unterminated CDATA section");
        const size_t b = p_;
        advance(e - p_);
        el.text += std::string(t_.substr(b, e - b));
        advance(3);
      } else if (starts("<?")) {
        skip_until("?>", "processing instruction");
      } else if (starts("<")) {
        el.children.push_back(std::make_unique<XmlElement>(element()));
      } else if (t_[p_] == '&') {
        entity(el.text);
      } else {
        el.text += t_[p_];
        advance(1);
      }
    }
  }

  std::string_view t_;
  const std::string& source_;
  size_t p_ = 0;
  size_t line_ = 1;
};

}  // namespace

XmlElement parse_xml(std::string_view text, const std::string& source) { return Parser(text, source).document(); }

}  // namespace gmr::io
