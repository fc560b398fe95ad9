#include "model/expr/ast.hpp"

#include <charconv>

namespace gmr::expr {

namespace {

std::string ref_text(const NodeRef& r) {
  std::string s = r.base;
  for (int d : r.path) s += "@" + std::to_string(d);
  return s;
}

std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

int precedence(const Expr& e) {
  switch (e.op) {
    case Expr::Op::Add:
    case Expr::Op::Sub:
      return 1;
    case Expr::Op::Mul:
    case Expr::Op::Div:
      return 2;
    case Expr::Op::Neg:
      return 3;
    case Expr::Op::Let:
      return 0;
    default:
      return 4;
  }
}

std::string wrap(const Expr& e, int min) {
  const std::string s = to_text(e);
  return precedence(e) < min ? "(" + s + ")" : s;
}

}  // namespace

std::string to_text(const Expr& e) {
  switch (e.op) {
    case Expr::Op::Number:
      return number_text(e.number);
    case Expr::Op::Constant:
      return e.name;
    case Expr::Op::Value:
      return ref_text(e.ref) + "." + e.name;
    case Expr::Op::Collect:
      return e.orbit.str() + "_" + e.name + "(" + ref_text(e.ref) + ")";
    case Expr::Op::Comprehension:
      if (!e.word.empty()) {
        std::string w;
        for (int d : e.word) w += "@" + std::to_string(d);
        return "[" + to_text(*e.args[0]) + " | " + e.name + ", " + e.index + " in (" + w + ")*(" +
               ref_text(e.ref) + ")]";
      }
      return "[" + to_text(*e.args[0]) + " | " + e.name + " in " + e.orbit.str() + "/" +
             e.classes.str() + "(" + ref_text(e.ref) + ")]";
    case Expr::Op::Call: {
      std::string s = e.name + "(";
      for (size_t k = 0; k < e.args.size(); ++k) s += (k ? ", " : "") + to_text(*e.args[k]);
      return s + ")";
    }
    case Expr::Op::Neg:
      return "-" + wrap(*e.args[0], 3);
    case Expr::Op::Let:
      return "let " + e.name + " = " + to_text(*e.args[0]) + " in " + to_text(*e.args[1]);
    case Expr::Op::Add:
      return wrap(*e.args[0], 1) + " + " + wrap(*e.args[1], 2);
    case Expr::Op::Sub:
      return wrap(*e.args[0], 1) + " - " + wrap(*e.args[1], 2);
    case Expr::Op::Mul:
      return wrap(*e.args[0], 2) + " * " + wrap(*e.args[1], 3);
    case Expr::Op::Div:
      return wrap(*e.args[0], 2) + " / " + wrap(*e.args[1], 3);
  }
  return "?";
}

}  // namespace gmr::expr
