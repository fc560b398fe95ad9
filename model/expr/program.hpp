// A checked embedding expression compiled once into a flat program (docs/embeddings.md,
// "Compiled expressions"): the tree in postfix order over a stack of values, constant
// sub-expressions folded, each node reference resolved to (node or variable, path). An aggregate
// over a multiset — middle, sum or count of a collect, a comprehension or a walk — is one
// instruction followed by the program of its body (the value of one member), which the evaluator
// runs once per member it enumerates (Algorithm 4, Evaluator::members); the instruction after the
// body continues the enclosing program.
//
// Node values are resolved at compile time to loads (LoadRef: node or variable, path, embedding;
// no reading of the tree at run time). An affine combination of node values with constant weights
// — Loop's edge mask (3(a+b)+c+d)/8, Catmull-Clark's (v1+v2+F1+F2)/4 — is fused (Combine): its
// terms, in the tree's order, accumulate into one value, acc = offset + sum w_i t_i, a run of loads
// in one instruction; another operand (a barycentre, a product by a let variable) runs its own
// program and is accumulated with its weight.
//
// A dart-free sub-expression (it reads let variables and constants only: Loop's vertex weight
// c = 5/8 - (3 + 2 cos(2 pi / k))^2 / 64 of the valence k) is a pure function of the let values in
// scope; its code is enclosed in Pure ... PureEnd, and the evaluator keeps its last results (eight)
// with the let values each was computed from (Evaluator::run): equal let values (bit for bit) give
// that result again without running the code. A run that fails keeps nothing.
//
// Semantics: those of the tree interpreter (Evaluator::evaluate on the Expr), which stays the
// general path and the oracle; folding uses the same operations as the evaluation, so the values
// are the same, and run-time errors name the same expression (column) and dart. A fused
// combination distributes its weights (3(a+b)/8 is 3/8 a + 3/8 b), so its value equals the tree's
// up to rounding (a few ulps), not bit for bit; its operands are read in the tree's order, so the
// errors are the same.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "model/expr/ast.hpp"

namespace gmr::expr {

// A node value resolved at compile time: the dart of left node `index` (or of the comprehension
// variable at depth `index`), then the links of `path`, then the embedding's value there.
struct LoadRef {
  static constexpr size_t kMaxPath = 6;  // longer paths stay Instruction::Op::Value
  const Expr* expr = nullptr;            // the Value node (errors)
  uint32_t index = 0;
  uint16_t embedding = 0;
  bool variable = false;
  uint8_t length = 0;
  uint8_t path[kMaxPath] = {};
  double weight = 1;  // in a fused combination
};

struct Instruction {
  enum class Op : uint8_t {
    Constant,      // push value
    LetGet,        // push the let variable `index`
    LetBind,       // pop into a new let variable
    LetDrop,       // drop the innermost let variable
    Value,         // push the embedding value at the referenced dart (expr->ref)
    Load,          // push the value of loads[index]
    Combine,       // push offset (value) + sum of weight * value over loads[index, index + count)
    CombineLoads,  // top += sum of weight * value over loads[index, index + count)
    Accumulate,    // pop v; top += value[0] * v
    Neg,
    Add,
    Sub,
    ScaleLeft,   // scalar * value (the scalar pushed first)
    ScaleRight,  // value * scalar
    Div,         // value / scalar
    Make,        // point, vector or colour of three scalars (expr->function)
    Cos,
    Sin,
    Abs,
    Sqrt,
    Dot,
    Cross,
    Norm,
    Clamp,
    AggregateArgs,  // middle/sum/count of the `index` values on top of the stack
    AggregateSet,   // middle/sum/count of the multiset expr->args[0]; body: the next `index`
                    // instructions
    Pure,           // a dart-free sub-expression of `index` instructions follows (see below)
    PureEnd,        // its end; `index`: its length
    Unknown,        // an unknown function (fails)
  };
  Op op = Op::Constant;
  const Expr* expr = nullptr;  // the node compiled (errors, references, multisets)
  uint32_t index = 0;
  uint32_t count = 0;
  double value[4] = {0, 0, 0, 0};
};

struct Program {
  const Expr* root = nullptr;  // the expression compiled (must outlive the program)
  std::vector<Instruction> code;
  std::vector<LoadRef> loads;  // Load, Combine, CombineLoads
  bool fused = false;          // has a fused combination (values equal the tree's up to rounding)
  uint64_t id = 0;             // unique per compile_program call (the evaluator's kept results)
  size_t max_stack = 0;        // values on the stack at most, nested bodies included
};

// The program of a checked expression; nullopt when its stack would exceed `stack_limit` values
// (the tree interpreter evaluates it then).
std::optional<Program> compile_program(const Expr& e, size_t stack_limit = 256);

}  // namespace gmr::expr
