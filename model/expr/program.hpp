// A checked embedding expression compiled once into a flat program (docs/embeddings.md,
// "Compiled expressions"): the tree in postfix order over a stack of values, constant
// sub-expressions folded, each node reference resolved to (node or variable, path). An aggregate
// over a multiset — middle, sum or count of a collect, a comprehension or a walk — is one
// instruction followed by the program of its body (the value of one member), which the evaluator
// runs once per member it enumerates (Algorithm 4, Evaluator::members); the instruction after the
// body continues the enclosing program.
//
// Semantics: those of the tree interpreter (Evaluator::evaluate on the Expr), which stays the
// general path and the oracle; folding uses the same operations as the evaluation, so the values
// are the same, and run-time errors name the same expression (column) and dart.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "model/expr/ast.hpp"

namespace gmr::expr {

struct Instruction {
  enum class Op : uint8_t {
    Constant,       // push value
    LetGet,         // push the let variable `index`
    LetBind,        // pop into a new let variable
    LetDrop,        // drop the innermost let variable
    Value,          // push the embedding value at the referenced dart (expr->ref)
    Neg, Add, Sub,
    ScaleLeft,      // scalar * value (the scalar pushed first)
    ScaleRight,     // value * scalar
    Div,            // value / scalar
    Make,           // point, vector or colour of three scalars (expr->function)
    Cos, Sin, Abs, Sqrt, Dot, Cross, Norm, Clamp,
    AggregateArgs,  // middle/sum/count of the `index` values on top of the stack
    AggregateSet,   // middle/sum/count of the multiset expr->args[0]; body: the next `index` instructions
    Unknown,        // an unknown function (fails)
  };
  Op op = Op::Constant;
  const Expr* expr = nullptr;  // the node compiled (errors, references, multisets)
  uint32_t index = 0;
  double value[4] = {0, 0, 0, 0};
};

struct Program {
  const Expr* root = nullptr;  // the expression compiled (must outlive the program)
  std::vector<Instruction> code;
  size_t max_stack = 0;  // values on the stack at most, nested bodies included
};

// The program of a checked expression; nullopt when its stack would exceed `stack_limit` values
// (the tree interpreter evaluates it then).
std::optional<Program> compile_program(const Expr& e, size_t stack_limit = 256);

}  // namespace gmr::expr
