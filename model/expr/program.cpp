#include "model/expr/program.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "model/expr/value_ops.hpp"

namespace gmr::expr {

namespace {

using Op = Instruction::Op;
using K = StaticType::Kind;

Instruction constant(const Expr& e, const Val& v) {
  Instruction i;
  i.op = Op::Constant;
  i.expr = &e;
  i.value[0] = v.x;
  i.value[1] = v.y;
  i.value[2] = v.z;
  i.value[3] = v.w;
  return i;
}

Val value_of(const Instruction& i) { return {i.value[0], i.value[1], i.value[2], i.value[3]}; }

class Compiler {
 public:
  // fuse: affine combinations fused (off for the constant test of a sub-expression).
  explicit Compiler(Program& p, bool fuse = true) : p_(p), fuse_(fuse) {}

  // Emits e's code; the stack grows by one value.
  void emit(const Expr& e) {
    if (fuse_ && !in_pure_ && worth_keeping(e)) {
      pure(e);
      return;
    }
    emit_plain(e);
  }

 private:
  void emit_plain(const Expr& e) {
    const size_t start = p_.code.size();
    switch (e.op) {
      case Expr::Op::Number:
        push(constant(e, {e.number, 0, 0, 0}));
        return;
      case Expr::Op::Constant:
        if (e.let_index >= 0) {
          push(simple(Op::LetGet, e, static_cast<uint32_t>(e.let_index)));
        } else {
          push(constant(e, {M_PI, 0, 0, 0}));
        }
        return;
      case Expr::Op::Let:
        emit(*e.args[0]);
        pop_to(simple(Op::LetBind, e), 1);
        emit(*e.args[1]);
        p_.code.push_back(simple(Op::LetDrop, e));
        return;
      case Expr::Op::Value:
        if (e.ref.path.size() <= LoadRef::kMaxPath) {
          push(simple(Op::Load, e, static_cast<uint32_t>(p_.loads.size())));
          p_.loads.push_back(load_of(e, 1.0));
        } else {
          push(simple(Op::Value, e));
        }
        return;
      case Expr::Op::Collect:
      case Expr::Op::Comprehension:
        break;  // only under an aggregate (type checker)
      case Expr::Op::Call:
        break;
      default:
        if (fuse_ && combination(e)) return;
        break;
    }
    switch (e.op) {
      case Expr::Op::Neg:
        unary(e, Op::Neg, start);
        return;
      case Expr::Op::Add:
        binary(e, Op::Add, start);
        return;
      case Expr::Op::Sub:
        binary(e, Op::Sub, start);
        return;
      case Expr::Op::Mul:
        binary(e, e.args[0]->type.kind == K::Scalar ? Op::ScaleLeft : Op::ScaleRight, start);
        return;
      case Expr::Op::Div:
        binary(e, Op::Div, start);
        return;
      default:
        break;
    }
    switch (e.function) {
      case Function::Point:
      case Function::Vector:
      case Function::Colour:
        for (const auto& a : e.args) emit(*a);
        finish(e, simple(Op::Make, e), 3, start);
        return;
      case Function::Middle:
      case Function::Sum:
      case Function::Count:
        if (e.args.size() == 1 && e.args[0]->type.kind == K::Multiset) {
          aggregate_set(e);
          return;
        }
        for (const auto& a : e.args) emit(*a);
        finish(e, simple(Op::AggregateArgs, e, static_cast<uint32_t>(e.args.size())), e.args.size(),
               start);
        return;
      case Function::Cos:
        unary(e, Op::Cos, start);
        return;
      case Function::Sin:
        unary(e, Op::Sin, start);
        return;
      case Function::Abs:
        unary(e, Op::Abs, start);
        return;
      case Function::Sqrt:
        unary(e, Op::Sqrt, start);
        return;
      case Function::Norm:
        unary(e, Op::Norm, start);
        return;
      case Function::Clamp:
        unary(e, Op::Clamp, start);
        return;
      case Function::Dot:
        binary(e, Op::Dot, start);
        return;
      case Function::Cross:
        binary(e, Op::Cross, start);
        return;
      case Function::None:
        break;
    }
    push(simple(Op::Unknown, e));  // not for checked expressions; the run fails on it
  }
  static Instruction simple(Op op, const Expr& e, uint32_t index = 0) {
    Instruction i;
    i.op = op;
    i.expr = &e;
    i.index = index;
    return i;
  }
  void push(const Instruction& i) {
    p_.code.push_back(i);
    ++depth_;
    p_.max_stack = std::max(p_.max_stack, depth_);
  }
  // An instruction that pops `n` values (LetBind: n = 1, pushes nothing).
  void pop_to(const Instruction& i, size_t n) {
    p_.code.push_back(i);
    depth_ -= n;
  }
  // An instruction that pops `n` values and pushes one; folded when its operands are constants
  // that the run would not reject (division by zero, square root of a negative number).
  void finish(const Expr& e, const Instruction& i, size_t n, size_t start) {
    if (p_.code.size() - start == n &&
        std::all_of(p_.code.begin() + static_cast<long>(start), p_.code.end(),
                    [](const Instruction& x) { return x.op == Op::Constant; })) {
      Val v[3];
      for (size_t k = 0; k < n; ++k) v[k] = value_of(p_.code[start + k]);
      std::optional<Val> r = fold(e, i, v, n);
      if (r) {
        p_.code.resize(start);
        depth_ -= n;
        push(constant(e, *r));
        return;
      }
    }
    p_.code.push_back(i);
    depth_ -= n;
    ++depth_;
  }
  void unary(const Expr& e, Op op, size_t start) {
    emit(*e.args[0]);
    finish(e, simple(op, e), 1, start);
  }
  void binary(const Expr& e, Op op, size_t start) {
    emit(*e.args[0]);
    emit(*e.args[1]);
    finish(e, simple(op, e), 2, start);
  }
  static std::optional<Val> fold(const Expr& e, const Instruction& i, const Val* v, size_t n) {
    switch (i.op) {
      case Op::Neg:
        return ops::neg(v[0]);
      case Op::Add:
        return ops::add(v[0], v[1]);
      case Op::Sub:
        return ops::sub(v[0], v[1]);
      case Op::ScaleLeft:
        return ops::scale(v[1], v[0].x);
      case Op::ScaleRight:
        return ops::scale(v[0], v[1].x);
      case Op::Div:
        if (v[1].x == 0.0) return std::nullopt;
        return ops::divide(v[0], v[1].x);
      case Op::Make:
        return ops::make(e.function, v[0], v[1], v[2]);
      case Op::Cos:
        return ops::cos(v[0]);
      case Op::Sin:
        return ops::sin(v[0]);
      case Op::Abs:
        return ops::abs(v[0]);
      case Op::Sqrt:
        if (v[0].x < 0) return std::nullopt;
        return ops::sqrt(v[0]);
      case Op::Norm:
        return ops::norm(v[0]);
      case Op::Clamp:
        return ops::clamp(v[0]);
      case Op::Dot:
        return ops::dot(v[0], v[1]);
      case Op::Cross:
        return ops::cross(v[0], v[1]);
      case Op::AggregateArgs: {
        if (n == 0 && e.function == Function::Middle) return std::nullopt;
        Val acc;
        for (size_t k = 0; k < n; ++k) acc = ops::add(acc, v[k]);
        return ops::finish_aggregate(e.function, acc, n);
      }
      default:
        return std::nullopt;
    }
  }
  // The multiset's members are enumerated by the evaluator; a comprehension's or a walk's body is
  // compiled right after the instruction, on top of the current stack.
  void aggregate_set(const Expr& e) {
    const Expr& m = *e.args[0];
    const size_t at = p_.code.size();
    p_.code.push_back(simple(Op::AggregateSet, e));
    if (m.op == Expr::Op::Comprehension) {
      const size_t saved = depth_;
      emit(*m.args[0]);
      depth_ = saved;
    }
    p_.code[at].index = static_cast<uint32_t>(p_.code.size() - at - 1);
    ++depth_;
    p_.max_stack = std::max(p_.max_stack, depth_);
  }

  static LoadRef load_of(const Expr& e, double weight) {
    LoadRef r;
    r.expr = &e;
    r.index = e.ref.index;
    r.variable = e.ref.is_variable;
    r.embedding = static_cast<uint16_t>(e.embedding);
    r.length = static_cast<uint8_t>(e.ref.path.size());
    for (size_t k = 0; k < e.ref.path.size(); ++k) r.path[k] = static_cast<uint8_t>(e.ref.path[k]);
    r.weight = weight;
    return r;
  }

  // The value of e when it folds to a constant (compiled apart: a single Constant instruction).
  static std::optional<Val> constant_of(const Expr& e) {
    Program q;
    Compiler(q, false).emit(e);
    if (q.code.size() == 1 && q.code[0].op == Op::Constant) return value_of(q.code[0]);
    return std::nullopt;
  }

  // An affine combination with constant weights: e = offset + sum weight_i * term_i, the terms in
  // the tree's evaluation order (left operand first).
  struct Term {
    double weight;
    const Expr* e;
    bool load;  // a node value (LoadRef), else a sub-expression with a program of its own
  };
  static void decompose(const Expr& e, double w, std::vector<Term>& terms, Val& offset) {
    if (const std::optional<Val> c = constant_of(e)) {
      offset = ops::add(offset, ops::scale(*c, w));
      return;
    }
    switch (e.op) {
      case Expr::Op::Add:
        decompose(*e.args[0], w, terms, offset);
        decompose(*e.args[1], w, terms, offset);
        return;
      case Expr::Op::Sub:
        decompose(*e.args[0], w, terms, offset);
        decompose(*e.args[1], -w, terms, offset);
        return;
      case Expr::Op::Neg:
        decompose(*e.args[0], -w, terms, offset);
        return;
      case Expr::Op::Mul:
        if (e.args[0]->type.kind == K::Scalar)
          if (const std::optional<Val> k = constant_of(*e.args[0])) {
            decompose(*e.args[1], w * k->x, terms, offset);
            return;
          }
        if (e.args[1]->type.kind == K::Scalar)
          if (const std::optional<Val> k = constant_of(*e.args[1])) {
            decompose(*e.args[0], w * k->x, terms, offset);
            return;
          }
        break;
      case Expr::Op::Div:
        if (const std::optional<Val> k = constant_of(*e.args[1]); k && k->x != 0.0) {
          decompose(*e.args[0], w * (1.0 / k->x), terms, offset);
          return;
        }
        break;  // a division by a run-time scalar, or by zero (reported by the run)
      case Expr::Op::Value:
        if (e.ref.path.size() <= LoadRef::kMaxPath) {
          terms.push_back({w, &e, true});
          return;
        }
        break;
      default:
        break;
    }
    terms.push_back({w, &e, false});
  }

  // Emits e as a fused combination when it has two node values or more (a run of loads then is
  // one instruction); the stack grows by one value.
  bool combination(const Expr& e) {
    if (e.type.kind == K::Multiset) return false;
    std::vector<Term> terms;
    Val offset;
    decompose(e, 1.0, terms, offset);
    if (std::count_if(terms.begin(), terms.end(), [](const Term& t) { return t.load; }) < 2)
      return false;
    p_.fused = true;
    for (size_t k = 0; k < terms.size();) {
      const bool first = k == 0;
      if (terms[k].load) {
        Instruction i = simple(first ? Op::Combine : Op::CombineLoads, e,
                               static_cast<uint32_t>(p_.loads.size()));
        for (; k < terms.size() && terms[k].load; ++k)
          p_.loads.push_back(load_of(*terms[k].e, terms[k].weight));
        i.count = static_cast<uint32_t>(p_.loads.size() - i.index);
        if (first) {
          const Instruction c = constant(e, offset);
          std::copy(c.value, c.value + 4, i.value);
          push(i);
        } else {
          p_.code.push_back(i);
        }
        continue;
      }
      if (first) push(constant(e, offset));
      emit(*terms[k].e);
      Instruction i = simple(Op::Accumulate, e);
      i.value[0] = terms[k].weight;
      pop_to(i, 1);
      ++k;
    }
    return true;
  }

  // Whether e reads no dart: numbers, pi, let variables and functions of them.
  static bool dart_free(const Expr& e) {
    switch (e.op) {
      case Expr::Op::Value:
      case Expr::Op::Collect:
      case Expr::Op::Comprehension:
        return false;
      case Expr::Op::Call:
        if (e.function == Function::None) return false;
        break;
      default:
        break;
    }
    return std::all_of(e.args.begin(), e.args.end(), [](const auto& a) { return dart_free(*a); });
  }
  static bool reads_let(const Expr& e) {
    if (e.op == Expr::Op::Constant && e.let_index >= 0) return true;
    return std::any_of(e.args.begin(), e.args.end(), [](const auto& a) { return reads_let(*a); });
  }
  // A dart-free sub-expression of a let variable, long enough for its kept result to pay (the
  // look-up costs about two instructions).
  static constexpr size_t kPureLength = 6;
  static bool worth_keeping(const Expr& e) {
    if (e.type.kind == K::Multiset || !reads_let(e) || !dart_free(e)) return false;
    Program q;
    Compiler(q, false).emit(e);
    return q.code.size() >= kPureLength;
  }
  void pure(const Expr& e) {
    const size_t at = p_.code.size();
    p_.code.push_back(simple(Op::Pure, e));
    in_pure_ = true;
    emit_plain(e);
    in_pure_ = false;
    const auto length = static_cast<uint32_t>(p_.code.size() - at - 1);
    p_.code[at].index = length;
    p_.code.push_back(simple(Op::PureEnd, e, length));
  }

  Program& p_;
  bool fuse_;
  bool in_pure_ = false;
  size_t depth_ = 0;
};

}  // namespace

std::optional<Program> compile_program(const Expr& e, size_t stack_limit) {
  static std::atomic<uint64_t> next_id{1};
  Program p;
  p.root = &e;
  p.id = next_id++;
  Compiler(p).emit(e);
  if (p.max_stack > stack_limit) return std::nullopt;
  return p;
}

}  // namespace gmr::expr
