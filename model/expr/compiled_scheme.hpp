// The embedding expressions of a rule scheme, parsed and type-checked against its embedding
// declarations (thesis §6.3.3: expressions on right nodes; docs/embeddings.md).
//
// Expressions read left nodes only (the object before the rewrite). At most one expression per
// node and embedding (S-UNIQ); an expression on a left-only node, for an undeclared embedding, or
// a declaration with an unknown value type, a malformed orbit type or a duplicate name is an error.
// Errors are thrown as gmr::Error located "rule <name>, R node <n>, embedding <e>, column <c>".
// Jerboa expressions that could not be translated (EmbeddingExpression::unsupported) are skipped.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "model/expr/ast.hpp"
#include "model/expr/type_check.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::expr {

struct CompiledScheme {
  const scheme::RuleScheme* scheme = nullptr;
  std::vector<EmbeddingSignature> embeddings;  // the declarations, in order
  // right[e][v]: the expression of right node v for embedding e, or nullptr.
  std::vector<std::vector<std::shared_ptr<const Expr>>> right;

  bool has_expressions(size_t e) const;
};

// The signatures of a scheme's declarations (Error(Schema) located "rule <name>, embedding <e>").
std::vector<EmbeddingSignature> embedding_signatures(const scheme::RuleScheme& s);
// The context expressions of `s` are checked in (left nodes readable).
CheckContext check_context(const scheme::RuleScheme& s,
                           const std::vector<EmbeddingSignature>& sigs);

// Parses and checks one expression of embedding `sig` (in `ctx`); `where` locates errors.
std::shared_ptr<const Expr> compile_expression(const std::string& code,
                                               const EmbeddingSignature& sig, CheckContext ctx,
                                               const std::string& where);

// Keeps a pointer to `s`, which must outlive the result.
CompiledScheme compile_scheme(const scheme::RuleScheme& s);

}  // namespace gmr::expr
