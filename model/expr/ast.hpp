// Abstract syntax of embedding expressions (docs/embeddings.md has the grammar).
//
// Identifier terms (thesis §5.5.1): a node reference n0@1@0 names the dart reached from the dart
// instantiating node n0 by following alpha_1 then alpha_0 (read left to right, Jerboa's syntax),
// on the object *before* the rewrite. Collects <o>_pi(ref) (thesis §5.5.2, Jerboa <o>_pi) give
// the multiset of pi-values, one per pi-orbit met in the <o>-orbit of ref. Comprehensions
// [e | x in <o>/<c>(ref)] generalise collects: one value of e per <c>-orbit met in <o>(ref), x
// bound to the first dart met of that <c>-orbit (so <o>_pi(r) is [x.pi | x in <o>/<o_pi>(r)]).
// A walk [e | x, k in (@i@j...)*(ref)] visits ref, ref w, ref w w, ... (the cycle of the word w
// through ref), with x the dart and k its rank.
// `let x = e1 in e2` names a value (args[0]) inside its body (args[1]).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "model/core/orbit_type.hpp"
#include "model/expr/type.hpp"

namespace gmr::expr {

struct NodeRef {
  std::string base;       // a rule node name or a comprehension variable
  std::vector<int> path;  // dimensions followed, in order
  size_t column = 0;
  // Resolved by the type checker: the left node index, or the comprehension variable's depth.
  bool is_variable = false;
  uint32_t index = 0;
};

// The functions of the language (type_check.cpp resolves the names, including synonyms).
enum class Function : uint8_t {
  None,
  Point,
  Vector,
  Colour,
  Middle,
  Sum,
  Count,
  Cos,
  Sin,
  Sqrt,
  Abs,
  Dot,
  Cross,
  Norm,
  Clamp
};

struct Expr {
  enum class Op {
    Number,
    Constant,
    Value,
    Collect,
    Comprehension,
    Call,
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Let
  };
  Op op = Op::Number;
  size_t column = 0;  // 1-based column of the expression's first character
  double number = 0;  // Number
  std::string name;   // Constant (pi or a let variable), Value/Collect: embedding, Call: function,
                      // Comprehension and Let: the variable
  NodeRef ref;        // Value, Collect, Comprehension
  OrbitType orbit;    // Collect, Comprehension: <o>
  OrbitType classes;  // Comprehension: <c>
  // Comprehension over a word walk [e | x, k in (@i@j...)*(ref)]: x = ref w^k for k = 0, 1, ...
  // until x is ref again (a cycle: the word is a permutation of the darts), k bound as a scalar.
  std::vector<int> word;
  std::string index;                        // the name of k (walks only)
  std::vector<std::unique_ptr<Expr>> args;  // operands, call arguments, comprehension body

  // Filled by the type checker.
  StaticType type;
  int embedding = -1;                  // Value/Collect: index of the embedding in the declarations
  int let_index = -1;                  // Constant naming a let variable: its depth
  Function function = Function::None;  // Call
  // Collect and Comprehension: the masks of <o> and of the classes told apart (<c>, or the
  // collected embedding's orbit <o_pi> for a collect).
  DimMask orbit_mask = 0, class_mask = 0;
};

// The expression text regenerated from the tree (normal spacing), for messages and round trips.
std::string to_text(const Expr& e);

}  // namespace gmr::expr
