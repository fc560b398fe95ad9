// The parser of embedding expressions (grammar in docs/embeddings.md). Recursive descent on the
// text; the first error is thrown as Error(Parse) located "<where>, column <c>" (1-based), e.g.
// "rule quad, R node n1, embedding position, column 12".
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "model/expr/ast.hpp"

namespace gmr::expr {

// Limits on hostile input (Error(Parse) beyond them): the length of one expression and the nesting
// of parentheses and unary operators.
inline constexpr size_t kMaxExpressionLength = 4096;
inline constexpr size_t kMaxExpressionNesting = 100;

std::unique_ptr<Expr> parse_expression(std::string_view text, const std::string& where = {});

}  // namespace gmr::expr
