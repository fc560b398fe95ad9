// Type checking of embedding expressions (thesis §5.5, S-TYPE in docs/embeddings.md).
//
// Resolves node references (left nodes of the rule: expressions read the object before the
// rewrite; comprehension variables shadow node names), embedding names, orbit types (dimensions
// 0..n) and function calls, and computes every sub-expression's StaticType. The expression's type
// must be its embedding's value type: a scalar, a colour, or an affine value whose mass is 1
// (point) or 0 (vector) — when the mass depends on run-time scalars (e.g. (q + (k-1)*p)/k) it is
// checked at evaluation. The first problem is thrown as Error(Schema) located
// "<where>, column <c>".
#pragma once
#include <string>
#include <vector>

#include "model/core/orbit_type.hpp"
#include "model/expr/ast.hpp"

namespace gmr::expr {

// An embedding pi : <o_pi> -> tau_pi as the expressions see it.
struct EmbeddingSignature {
  std::string name;
  OrbitType orbit;
  ValueType type = ValueType::Point;
};

struct CheckContext {
  int dimension = 2;
  std::vector<std::string> nodes;       // readable nodes (left nodes of the rule)
  std::vector<std::string> right_only;  // added nodes (named in the message when referenced)
  std::vector<EmbeddingSignature> embeddings;
  std::string where;
};

// Checks `e` (annotating it) as a value of `target`; returns its static type.
StaticType check_expression(Expr& e, const CheckContext& ctx, ValueType target);

// The names of the functions and constants of the language, for the documentation and messages.
const std::vector<std::string>& function_names();

}  // namespace gmr::expr
