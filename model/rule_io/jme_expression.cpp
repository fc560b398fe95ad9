#include "model/rule_io/jme_expression.hpp"

#include <cctype>
#include <charconv>
#include <map>
#include <vector>

namespace gmr::io {

namespace {

struct Unsupported {
  std::string why;
};

class Translator {
 public:
  explicit Translator(const std::string& t) : t_(t) {}

  std::string body() {
    for (;;) {
      skip();
      if (pos_ >= t_.size()) throw Unsupported{"no return statement"};
      const size_t save = pos_;
      const std::string first = ident();
      if (first == "return") {
        std::string e = expr();
        expect(';');
        skip();
        if (pos_ < t_.size()) throw Unsupported{"code after the return statement"};
        return e;
      }
      if (first == "Vec3" || first == "Point3" || first == "Color" || first == "Color3" ||
          first == "double" || first == "float") {  // declaration
        const std::string var = ident();
        expect('=');
        skip();
        if (t_.compare(pos_, 10, "new Vec3()") == 0 || t_.compare(pos_, 12, "new Point3()") == 0) {
          pos_ = t_.find(')', pos_) + 1;
          vars_[var] = "";  // set by a following barycenter
        } else {
          vars_[var] = expr();
        }
        expect(';');
        continue;
      }
      // v.barycenter(M);
      if (vars_.count(first) && accept('.')) {
        const std::string method = ident();
        if (method != "barycenter") throw Unsupported{"method " + method + " on a local variable"};
        expect('(');
        const std::string m = expr();
        expect(')');
        expect(';');
        vars_[first] = "middle(" + m + ")";
        continue;
      }
      pos_ = save;
      throw Unsupported{"statement '" + line() + "'"};
    }
  }

 private:
  void skip() {
    while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip();
    if (pos_ < t_.size() && t_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) throw Unsupported{std::string("expected '") + c + "' at '" + line() + "'"};
  }
  std::string line() const {
    const size_t e = t_.find_first_of(";\n", pos_);
    return t_.substr(pos_, e == std::string::npos ? std::string::npos : e - pos_);
  }
  std::string ident() {
    skip();
    const size_t b = pos_;
    while (pos_ < t_.size() &&
           (std::isalnum(static_cast<unsigned char>(t_[pos_])) || t_[pos_] == '_'))
      ++pos_;
    if (b == pos_) throw Unsupported{"unexpected '" + line() + "'"};
    return t_.substr(b, pos_ - b);
  }
  std::string number() {
    skip();
    const size_t b = pos_;
    if (pos_ < t_.size() && (t_[pos_] == '-' || t_[pos_] == '+')) ++pos_;
    while (pos_ < t_.size() &&
           (std::isdigit(static_cast<unsigned char>(t_[pos_])) || t_[pos_] == '.'))
      ++pos_;
    std::string s = t_.substr(b, pos_ - b);
    if (pos_ < t_.size() &&
        (t_[pos_] == 'f' || t_[pos_] == 'd' || t_[pos_] == 'F' || t_[pos_] == 'D'))
      ++pos_;
    double v = 0;
    if (s.empty() ||
        std::from_chars(s.data() + (s[0] == '+'), s.data() + s.size(), v).ec != std::errc())
      throw Unsupported{"expected a number at '" + line() + "'"};
    return s;
  }
  std::vector<std::string> args() {
    std::vector<std::string> out;
    expect('(');
    if (accept(')')) return out;
    for (;;) {
      out.push_back(expr());
      if (accept(')')) return out;
      expect(',');
    }
  }
  std::vector<std::string> numbers3() {
    std::vector<std::string> out;
    expect('(');
    for (int k = 0; k < 3; ++k) {
      if (k) expect(',');
      out.push_back(number());
    }
    expect(')');
    return out;
  }
  static bool is_number(const std::string& s) {
    double v = 0;
    return !s.empty() &&
           std::from_chars(s.data() + (s[0] == '+'), s.data() + s.size(), v).ec == std::errc() &&
           std::from_chars(s.data() + (s[0] == '+'), s.data() + s.size(), v).ptr ==
               s.data() + s.size();
  }

  std::string expr() {
    std::string e = primary();
    while (accept('.')) {  // method calls
      const std::string m = ident();
      if (m == "addn") {
        const auto v = numbers3();
        e = "(" + e + " + vector(" + v[0] + ", " + v[1] + ", " + v[2] + "))";
      } else {
        throw Unsupported{"method " + m};
      }
    }
    return e;
  }

  std::string primary() {
    skip();
    if (pos_ >= t_.size()) throw Unsupported{"unexpected end"};
    const char c = t_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.') return number();
    if (c == '<') {  // collect <o>_ebd(node)
      const size_t e = t_.find(')', pos_);
      if (e == std::string::npos) throw Unsupported{"unclosed collect"};
      std::string s = t_.substr(pos_, e + 1 - pos_);
      pos_ = e + 1;
      return s;
    }
    const std::string id = ident();
    if (id == "new") {
      const std::string type = ident();
      if (type == "Vec3" || type == "Point3") {
        const auto a = args();
        if (a.size() == 3 && is_number(a[0]) && is_number(a[1]) && is_number(a[2]))
          return "point(" + a[0] + ", " + a[1] + ", " + a[2] + ")";
        if (a.size() == 1) return a[0];
        throw Unsupported{"new " + type + " with these arguments"};
      }
      if (type == "Color" || type == "Color3") {
        const auto a = numbers3();
        if (type == "Color3") return "colour(" + a[0] + ", " + a[1] + ", " + a[2] + ")";
        return "colour(" + a[0] + " / 255, " + a[1] + " / 255, " + a[2] + " / 255)";
      }
      throw Unsupported{"new " + type};
    }
    if ((id == "Vec3" || id == "Point3") && accept('.')) {
      const std::string f = ident();
      if (f == "mid" || f == "middle") {
        const auto a = args();
        if (a.size() == 1) return "middle(" + a[0] + ")";
        if (a.size() == 2) return "middle(" + a[0] + ", " + a[1] + ")";
      }
      throw Unsupported{id + "." + f};
    }
    if (auto it = vars_.find(id); it != vars_.end()) {
      if (it->second.empty()) throw Unsupported{"variable " + id + " used before its value"};
      return "(" + it->second + ")";
    }
    // node value: n0.pos or n0@1@0.pos
    std::string ref = id;
    while (accept('@')) {
      skip();
      const size_t b = pos_;
      while (pos_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[pos_]))) ++pos_;
      if (b == pos_) throw Unsupported{"'@' without a dimension"};
      ref += "@" + t_.substr(b, pos_ - b);
    }
    skip();
    if (pos_ < t_.size() && t_[pos_] == '.') {
      const size_t save = pos_;
      ++pos_;
      const std::string field = ident();
      skip();
      if (pos_ < t_.size() && t_[pos_] == '(') {  // a method, not an embedding
        pos_ = save;
        throw Unsupported{"method " + field + " on " + ref};
      }
      return ref + "." + field;
    }
    throw Unsupported{"the name " + id + " (a rule parameter or Java code)"};
  }

  const std::string& t_;
  size_t pos_ = 0;
  std::map<std::string, std::string> vars_;
};

}  // namespace

JerboaTranslation translate_jerboa_expression(const std::string& java) {
  try {
    Translator t(java);
    return {t.body(), {}};
  } catch (const Unsupported& u) {
    return {std::nullopt, u.why};
  }
}

}  // namespace gmr::io
