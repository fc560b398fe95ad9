#include "model/expr/type_check.hpp"

#include <algorithm>
#include <cmath>

#include "model/core/error.hpp"

namespace gmr::expr {

namespace {
using K = StaticType::Kind;

class Checker {
 public:
  explicit Checker(const CheckContext& c) : c_(c) {}

  StaticType check(Expr& e) {
    e.type = infer(e);
    return e.type;
  }

 private:
  [[noreturn]] void fail(const Expr& e, const std::string& msg) const { fail_at(e.column, msg); }
  [[noreturn]] void fail_at(size_t col, const std::string& msg) const {
    throw Error(ErrorCode::Schema, msg,
                (c_.where.empty() ? "" : c_.where + ", ") + "column " + std::to_string(col));
  }

  void resolve(NodeRef& r) {
    for (size_t k = vars_.size(); k-- > 0;)
      if (vars_[k] == r.base) {
        r.is_variable = true;
        r.index = static_cast<uint32_t>(k);
        return check_path(r);
      }
    const auto it = std::find(c_.nodes.begin(), c_.nodes.end(), r.base);
    if (it == c_.nodes.end()) {
      if (std::find(c_.right_only.begin(), c_.right_only.end(), r.base) != c_.right_only.end())
        fail_at(r.column,
                "node " + r.base +
                    " is added by the rule: expressions read the object before the rewrite, "
                    "through left nodes only");
      fail_at(r.column, "unknown node " + r.base);
    }
    r.is_variable = false;
    r.index = static_cast<uint32_t>(it - c_.nodes.begin());
    check_path(r);
  }
  void check_path(const NodeRef& r) const {
    for (int d : r.path)
      if (d < 0 || d > c_.dimension)
        fail_at(r.column,
                "dimension " + std::to_string(d) + " outside 0.." + std::to_string(c_.dimension));
  }
  void check_orbit(const Expr& e, const OrbitType& o) const {
    for (int d : o.dims())
      if (d < 0 || d > c_.dimension)
        fail(e, "orbit type " + o.str() + " uses dimension " + std::to_string(d) + " outside 0.." +
                    std::to_string(c_.dimension));
  }
  int embedding(const Expr& e) const {
    for (size_t k = 0; k < c_.embeddings.size(); ++k)
      if (c_.embeddings[k].name == e.name) return static_cast<int>(k);
    std::string known;
    for (const auto& s : c_.embeddings) known += (known.empty() ? "" : ", ") + s.name;
    fail(e,
         "unknown embedding '" + e.name + "' (declared: " + (known.empty() ? "none" : known) + ")");
  }

  static bool is_value(const StaticType& t) { return t.kind != K::Multiset; }

  StaticType arith(Expr& e) {
    StaticType a = check(*e.args[0]), b = check(*e.args[1]);
    const char* sym = e.op == Expr::Op::Add   ? "+"
                      : e.op == Expr::Op::Sub ? "-"
                      : e.op == Expr::Op::Mul ? "*"
                                              : "/";
    auto bad = [&]() -> StaticType {
      fail(e, std::string("no operator ") + a.str() + " " + sym + " " + b.str());
    };
    if (a.kind == K::Multiset || b.kind == K::Multiset) bad();
    if (e.op == Expr::Op::Add || e.op == Expr::Op::Sub) {
      if (a.kind != b.kind) bad();
      if (a.kind == K::Scalar) {
        std::optional<double> c;
        if (a.constant && b.constant)
          c = e.op == Expr::Op::Add ? *a.constant + *b.constant : *a.constant - *b.constant;
        return StaticType::scalar(c);
      }
      if (a.kind == K::Colour) return StaticType::colour();
      std::optional<double> m;
      if (a.mass && b.mass) m = e.op == Expr::Op::Add ? *a.mass + *b.mass : *a.mass - *b.mass;
      return StaticType::affine(m);
    }
    if (e.op == Expr::Op::Mul) {
      if (a.kind == K::Scalar && b.kind == K::Scalar) {
        std::optional<double> c;
        if (a.constant && b.constant) c = *a.constant * *b.constant;
        return StaticType::scalar(c);
      }
      const StaticType& k = a.kind == K::Scalar ? a : b;
      const StaticType& x = a.kind == K::Scalar ? b : a;
      if (k.kind != K::Scalar) bad();
      if (x.kind == K::Colour) return StaticType::colour();
      return StaticType::affine(scale_mass(x.mass, k.constant));
    }
    // Div: x / scalar
    if (b.kind != K::Scalar) bad();
    if (a.kind == K::Scalar) {
      std::optional<double> c;
      if (a.constant && b.constant && *b.constant != 0) c = *a.constant / *b.constant;
      return StaticType::scalar(c);
    }
    if (a.kind == K::Colour) return StaticType::colour();
    std::optional<double> inv;
    if (b.constant && *b.constant != 0) inv = 1.0 / *b.constant;
    return StaticType::affine(scale_mass(a.mass, inv));
  }
  static std::optional<double> scale_mass(std::optional<double> m, std::optional<double> k) {
    if (m && *m == 0.0) return 0.0;  // a vector stays a vector
    if (m && k) return *m * *k;
    return std::nullopt;
  }

  static Function function_of(const std::string& f) {
    if (f == "point") return Function::Point;
    if (f == "vector") return Function::Vector;
    if (f == "colour" || f == "color") return Function::Colour;
    if (f == "middle" || f == "barycenter" || f == "barycentre" || f == "center" || f == "mix")
      return Function::Middle;
    if (f == "sum") return Function::Sum;
    if (f == "count") return Function::Count;
    if (f == "cos") return Function::Cos;
    if (f == "sin") return Function::Sin;
    if (f == "sqrt") return Function::Sqrt;
    if (f == "abs") return Function::Abs;
    if (f == "dot") return Function::Dot;
    if (f == "cross") return Function::Cross;
    if (f == "norm") return Function::Norm;
    if (f == "clamp") return Function::Clamp;
    return Function::None;
  }

  StaticType call(Expr& e) {
    const std::string& f = e.name;
    e.function = function_of(f);
    std::vector<StaticType> t;
    for (auto& a : e.args) t.push_back(check(*a));
    auto arity = [&](size_t n) {
      if (t.size() != n)
        fail(e, f + " takes " + std::to_string(n) + " argument(s), " + std::to_string(t.size()) +
                    " given");
    };
    auto scalars = [&]() {
      for (size_t k = 0; k < t.size(); ++k)
        if (t[k].kind != K::Scalar)
          fail(*e.args[k], f + " expects a scalar here, found " + t[k].str());
    };
    auto constant1 = [&](double (*fn)(double)) -> std::optional<double> {
      if (t[0].constant) return fn(*t[0].constant);
      return std::nullopt;
    };
    if (f == "point" || f == "vector" || f == "colour" || f == "color") {
      arity(3);
      scalars();
      if (f == "point") return StaticType::affine(1.0);
      if (f == "vector") return StaticType::affine(0.0);
      return StaticType::colour();
    }
    if (f == "middle" || f == "barycenter" || f == "barycentre" || f == "center" || f == "mix") {
      if (t.size() == 1) {
        if (t[0].kind != K::Multiset)
          fail(e, f + " of one argument takes a multiset (a collect), found " + t[0].str());
        return t[0].element_type();
      }
      if (t.size() < 2) fail(e, f + " takes a multiset or at least two values");
      for (size_t k = 0; k < t.size(); ++k)
        if (t[k].kind != t[0].kind || !is_value(t[k]))
          fail(*e.args[k], f + " mixes " + t[0].str() + " and " + t[k].str());
      if (t[0].kind == K::Affine) {
        std::optional<double> m = 0.0;
        for (const auto& x : t)
          m = (m && x.mass) ? std::optional<double>(*m + *x.mass) : std::nullopt;
        return StaticType::affine(m ? std::optional<double>(*m / static_cast<double>(t.size()))
                                    : std::nullopt);
      }
      return t[0].kind == K::Scalar ? StaticType::scalar() : StaticType::colour();
    }
    if (f == "sum") {
      arity(1);
      if (t[0].kind != K::Multiset) fail(e, "sum takes a multiset, found " + t[0].str());
      const StaticType el = t[0].element_type();
      if (el.kind == K::Affine) return StaticType::affine(scale_mass(el.mass, std::nullopt));
      return el.kind == K::Scalar ? StaticType::scalar() : StaticType::colour();
    }
    if (f == "count") {
      arity(1);
      if (t[0].kind != K::Multiset) fail(e, "count takes a multiset, found " + t[0].str());
      return StaticType::scalar();
    }
    if (f == "cos" || f == "sin" || f == "sqrt" || f == "abs") {
      arity(1);
      scalars();
      double (*fn)(double) = f == "cos"    ? static_cast<double (*)(double)>(std::cos)
                             : f == "sin"  ? static_cast<double (*)(double)>(std::sin)
                             : f == "sqrt" ? static_cast<double (*)(double)>(std::sqrt)
                                           : static_cast<double (*)(double)>(std::fabs);
      return StaticType::scalar(constant1(fn));
    }
    if (f == "dot" || f == "cross") {
      arity(2);
      for (size_t k = 0; k < 2; ++k)
        if (t[k].kind != K::Affine || !t[k].mass || *t[k].mass != 0.0)
          fail(*e.args[k], f + " takes vectors, found " + t[k].str());
      return f == "dot" ? StaticType::scalar() : StaticType::affine(0.0);
    }
    if (f == "norm") {
      arity(1);
      if (t[0].kind != K::Affine || !t[0].mass || *t[0].mass != 0.0)
        fail(e, "norm takes a vector, found " + t[0].str());
      return StaticType::scalar();
    }
    if (f == "clamp") {
      arity(1);
      if (t[0].kind != K::Colour) fail(e, "clamp takes a colour, found " + t[0].str());
      return StaticType::colour();
    }
    fail(e, "unknown function " + f);
  }

  StaticType infer(Expr& e) {
    switch (e.op) {
      case Expr::Op::Number:
        return StaticType::scalar(e.number);
      case Expr::Op::Constant:
        for (size_t k = lets_.size(); k-- > 0;)
          if (lets_[k].first == e.name) {
            e.let_index = static_cast<int>(k);
            return lets_[k].second;
          }
        if (e.name == "pi") return StaticType::scalar(M_PI);
        fail(e, "unknown name " + e.name + " (a node value is written node.embedding)");
      case Expr::Op::Value: {
        resolve(e.ref);
        e.embedding = embedding(e);
        return StaticType::of(c_.embeddings[static_cast<size_t>(e.embedding)].type);
      }
      case Expr::Op::Collect: {
        check_orbit(e, e.orbit);
        resolve(e.ref);
        e.embedding = embedding(e);
        e.orbit_mask = e.orbit.mask();
        e.class_mask = c_.embeddings[static_cast<size_t>(e.embedding)].orbit.mask();
        return StaticType::multiset(
            StaticType::of(c_.embeddings[static_cast<size_t>(e.embedding)].type));
      }
      case Expr::Op::Comprehension: {
        check_orbit(e, e.orbit);
        check_orbit(e, e.classes);
        for (int d : e.word)
          if (d < 0 || d > c_.dimension)
            fail(e,
                 "dimension " + std::to_string(d) + " outside 0.." + std::to_string(c_.dimension));
        resolve(e.ref);
        e.orbit_mask = e.orbit.mask();
        e.class_mask = e.classes.mask();
        vars_.push_back(e.name);
        if (!e.word.empty()) lets_.emplace_back(e.index, StaticType::scalar());
        const StaticType body = check(*e.args[0]);
        if (!e.word.empty()) lets_.pop_back();
        vars_.pop_back();
        if (!is_value(body))
          fail(*e.args[0], "a comprehension's body must be a value, found " + body.str());
        return StaticType::multiset(body);
      }
      case Expr::Op::Call:
        return call(e);
      case Expr::Op::Let: {
        const StaticType v = check(*e.args[0]);
        if (!is_value(v)) fail(*e.args[0], "a let variable names a value, not a " + v.str());
        lets_.emplace_back(e.name, v);
        const StaticType body = check(*e.args[1]);
        lets_.pop_back();
        return body;
      }
      case Expr::Op::Neg: {
        const StaticType a = check(*e.args[0]);
        if (a.kind == K::Multiset) fail(e, "no operator -" + a.str());
        if (a.kind == K::Scalar)
          return StaticType::scalar(a.constant ? std::optional<double>(-*a.constant)
                                               : std::nullopt);
        if (a.kind == K::Colour) return StaticType::colour();
        return StaticType::affine(a.mass ? std::optional<double>(-*a.mass) : std::nullopt);
      }
      case Expr::Op::Add:
      case Expr::Op::Sub:
      case Expr::Op::Mul:
      case Expr::Op::Div:
        return arith(e);
    }
    fail(e, "unknown expression");
  }

  const CheckContext& c_;
  std::vector<std::string> vars_;
  std::vector<std::pair<std::string, StaticType>> lets_;
};

}  // namespace

StaticType check_expression(Expr& e, const CheckContext& ctx, ValueType target) {
  Checker c(ctx);
  const StaticType t = c.check(e);
  const StaticType want = StaticType::of(target);
  bool ok = t.kind == want.kind;
  if (ok && t.kind == K::Affine && t.mass) ok = std::fabs(*t.mass - *want.mass) < 1e-12;
  if (!ok)
    throw Error(ErrorCode::Schema,
                std::string("the expression is ") + (t.str()[0] == 'a' ? "an " : "a ") + t.str() +
                    ", the embedding holds " + to_string(target) + " values",
                (ctx.where.empty() ? "" : ctx.where + ", ") + "column " + std::to_string(e.column));
  return t;
}

const std::vector<std::string>& function_names() {
  static const std::vector<std::string> names = {
      "point",  "vector", "colour", "color", "middle", "barycenter", "barycentre",
      "center", "mix",    "sum",    "count", "cos",    "sin",        "sqrt",
      "abs",    "dot",    "cross",  "norm",  "clamp",  "pi"};
  return names;
}

}  // namespace gmr::expr
