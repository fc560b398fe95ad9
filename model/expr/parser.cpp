#include "model/expr/parser.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "model/core/error.hpp"

namespace gmr::expr {

namespace {

class Parser {
 public:
  Parser(std::string_view text, const std::string& where) : t_(text), where_(where) {}

  std::unique_ptr<Expr> run() {
    // Bounds that keep the recursive descent, the tree's destruction and its evaluation within
    // the stack on hostile input: the length bounds the depth of left-nested operator chains.
    if (t_.size() > kMaxExpressionLength)
      fail("expression of " + std::to_string(t_.size()) + " characters, longer than " +
               std::to_string(kMaxExpressionLength),
           0);
    skip();
    if (pos_ >= t_.size()) fail("empty expression");
    auto e = sum();
    skip();
    if (pos_ < t_.size()) fail(std::string("unexpected '") + t_[pos_] + "' after the expression");
    return e;
  }

 private:
  // One level of unary operators or parentheses (every nesting passes through unary()).
  struct NestingGuard {
    Parser& p;
    explicit NestingGuard(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxExpressionNesting)
        p.fail("nesting deeper than " + std::to_string(kMaxExpressionNesting) + " levels");
    }
    ~NestingGuard() { --p.depth_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;
  };
  size_t depth_ = 0;

  [[noreturn]] void fail(const std::string& msg, size_t at = SIZE_MAX) const {
    const size_t col = (at == SIZE_MAX ? pos_ : at) + 1;
    throw Error(ErrorCode::Parse, msg,
                (where_.empty() ? "" : where_ + ", ") + "column " + std::to_string(col));
  }
  void skip() {
    while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) ++pos_;
  }
  bool peek(char c) {
    skip();
    return pos_ < t_.size() && t_[pos_] == c;
  }
  bool accept(char c) {
    if (!peek(c)) return false;
    ++pos_;
    return true;
  }
  void expect(char c, const char* what) {
    if (!accept(c)) fail(std::string("expected '") + c + "' " + what);
  }
  static bool ident_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
  }
  static bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
  std::string ident(const char* what) {
    skip();
    if (pos_ >= t_.size() || !ident_start(t_[pos_])) fail(std::string("expected ") + what);
    const size_t b = pos_;
    while (pos_ < t_.size() && ident_char(t_[pos_])) ++pos_;
    return std::string(t_.substr(b, pos_ - b));
  }
  int integer(const char* what) {
    skip();
    const size_t b = pos_;
    while (pos_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[pos_]))) ++pos_;
    if (b == pos_) fail(std::string("expected ") + what);
    int v = 0;
    const auto r = std::from_chars(t_.data() + b, t_.data() + pos_, v);
    if (r.ec != std::errc()) fail("dimension out of range", b);
    return v;
  }
  std::unique_ptr<Expr> make(Expr::Op op, size_t col) {
    auto e = std::make_unique<Expr>();
    e->op = op;
    e->column = col + 1;
    return e;
  }

  // operand ((c1|c2) operand)*, left-associative: c1 makes op1, c2 makes op2.
  std::unique_ptr<Expr> left_associative(std::unique_ptr<Expr> (Parser::*operand)(), char c1,
                                         Expr::Op op1, char c2, Expr::Op op2) {
    auto e = (this->*operand)();
    for (;;) {
      skip();
      const size_t at = pos_;
      Expr::Op op;
      if (accept(c1))
        op = op1;
      else if (accept(c2))
        op = op2;
      else
        return e;
      auto n = make(op, at);
      n->column = e->column;
      n->args.push_back(std::move(e));
      n->args.push_back((this->*operand)());
      e = std::move(n);
    }
  }
  // sum := product (('+'|'-') product)*
  std::unique_ptr<Expr> sum() {
    return left_associative(&Parser::product, '+', Expr::Op::Add, '-', Expr::Op::Sub);
  }
  // product := unary (('*'|'/') unary)*
  std::unique_ptr<Expr> product() {
    return left_associative(&Parser::unary, '*', Expr::Op::Mul, '/', Expr::Op::Div);
  }
  std::unique_ptr<Expr> unary() {
    const NestingGuard guard(*this);
    skip();
    const size_t at = pos_;
    if (accept('-')) {
      auto n = make(Expr::Op::Neg, at);
      n->args.push_back(unary());
      return n;
    }
    if (accept('+')) return unary();
    return primary();
  }
  // <d,d,...> without `_`
  OrbitType orbit_type() {
    skip();
    const size_t at = pos_;
    expect('<', "to open an orbit type");
    std::vector<int> dims;
    if (!accept('>')) {
      for (;;) {
        dims.push_back(integer("a dimension"));
        if (accept('>')) break;
        expect(',', "or '>' in the orbit type");
      }
    }
    OrbitType o(dims);
    // The range first: mask() shifts by each dimension.
    if (std::any_of(dims.begin(), dims.end(), [](int d) { return d < 0 || d >= kMaxDim; }) ||
        __builtin_popcount(o.mask()) != static_cast<int>(dims.size()))
      fail("the orbit type " + o.str() + " repeats a dimension or is out of range", at);
    return o;
  }
  NodeRef node_ref() {
    skip();
    NodeRef r;
    r.column = pos_ + 1;
    r.base = ident("a node name");
    while (accept('@')) r.path.push_back(integer("a dimension after '@'"));
    return r;
  }
  std::unique_ptr<Expr> number() {
    skip();
    const size_t b = pos_;
    double v = 0;
    const auto r = std::from_chars(t_.data() + pos_, t_.data() + t_.size(), v);
    if (r.ec != std::errc()) fail("malformed number");
    pos_ = static_cast<size_t>(r.ptr - t_.data());
    // Java float/double suffixes (Jerboa code: 0.4f).
    if (pos_ < t_.size() &&
        (t_[pos_] == 'f' || t_[pos_] == 'd' || t_[pos_] == 'F' || t_[pos_] == 'D') &&
        (pos_ + 1 >= t_.size() || !ident_char(t_[pos_ + 1])))
      ++pos_;
    auto e = make(Expr::Op::Number, b);
    e->number = v;
    return e;
  }
  std::unique_ptr<Expr> primary() {
    skip();
    if (pos_ >= t_.size()) fail("unexpected end of the expression");
    const size_t at = pos_;
    const char c = t_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (c == '(') {
      ++pos_;
      auto e = sum();
      expect(')', "to close '('");
      return e;
    }
    if (c == '<') {  // collect <o>_pi(ref)
      auto e = make(Expr::Op::Collect, at);
      e->orbit = orbit_type();
      if (pos_ >= t_.size() || t_[pos_] != '_')
        fail("expected '_' and an embedding name after the orbit type");
      ++pos_;
      e->name = ident("an embedding name");
      expect('(', "after the collected embedding");
      e->ref = node_ref();
      expect(')', "to close the collect");
      return e;
    }
    if (c == '[') {  // [body | x in <o>/<c>(ref)]
      ++pos_;
      auto e = make(Expr::Op::Comprehension, at);
      e->args.push_back(sum());
      expect('|', "after the body of the comprehension");
      e->name = ident("a dart variable");
      if (accept(',')) e->index = ident("an index variable after ','");
      skip();
      const size_t kw = pos_;
      if (ident("'in'") != "in") fail("expected 'in'", kw);
      if (!e->index.empty()) {  // (@i@j...)*(ref)
        expect('(', "to open the walked word, e.g. (@0@1)*");
        while (accept('@')) e->word.push_back(integer("a dimension after '@'"));
        if (e->word.empty()) fail("expected a word of dimensions, e.g. (@0@1)");
        expect(')', "to close the word");
        expect('*', "after the word (a walk repeats it)");
        expect('(', "before the walk's dart");
        e->ref = node_ref();
        expect(')', "after the walk's dart");
        expect(']', "to close the comprehension");
        return e;
      }
      e->orbit = orbit_type();
      expect('/', "between the orbit type and the class orbit type");
      e->classes = orbit_type();
      expect('(', "before the comprehension's dart");
      e->ref = node_ref();
      expect(')', "after the comprehension's dart");
      expect(']', "to close the comprehension");
      return e;
    }
    if (!ident_start(c)) fail(std::string("unexpected '") + c + "'");
    const size_t save = pos_;
    const std::string id = ident("a name");
    if (id == "let") {  // let x = e1 in e2 (the body extends as far as possible)
      auto e = make(Expr::Op::Let, at);
      e->name = ident("a variable name after 'let'");
      expect('=', "after the let variable");
      e->args.push_back(sum());
      skip();
      const size_t kw = pos_;
      if (pos_ >= t_.size() || !ident_start(t_[pos_]) || ident("'in'") != "in")
        fail("expected 'in' after the let value", kw);
      e->args.push_back(sum());
      return e;
    }
    if (accept('(')) {
      auto e = make(Expr::Op::Call, at);
      e->name = id;
      if (!accept(')')) {
        for (;;) {
          e->args.push_back(sum());
          if (accept(')')) break;
          expect(',', "or ')' in the argument list");
        }
      }
      return e;
    }
    skip();
    if (pos_ < t_.size() && (t_[pos_] == '.' || t_[pos_] == '@')) {
      pos_ = save;
      auto e = make(Expr::Op::Value, at);
      e->ref = node_ref();
      expect('.', "and an embedding name after the node");
      e->name = ident("an embedding name after '.'");
      return e;
    }
    auto e = make(Expr::Op::Constant, at);
    e->name = id;
    return e;
  }

  std::string_view t_;
  std::string where_;
  size_t pos_ = 0;
};

}  // namespace

std::unique_ptr<Expr> parse_expression(std::string_view text, const std::string& where) {
  return Parser(text, where).run();
}

}  // namespace gmr::expr
