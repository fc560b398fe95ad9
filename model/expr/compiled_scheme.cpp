#include "model/expr/compiled_scheme.hpp"

#include "model/core/error.hpp"
#include "model/expr/parser.hpp"

namespace gmr::expr {

bool CompiledScheme::has_expressions(size_t e) const {
  for (const auto& x : right[e])
    if (x) return true;
  return false;
}

std::vector<EmbeddingSignature> embedding_signatures(const scheme::RuleScheme& s) {
  std::vector<EmbeddingSignature> out;
  for (const auto& d : s.embeddings) {
    const std::string where = "rule " + s.name + ", embedding " + d.name;
    const auto t = parse_value_type(d.type);
    if (!t)
      throw Error(ErrorCode::Schema,
                  "unknown value type '" + d.type + "' (point, vector, scalar, colour)", where);
    if (d.orbit.has_hole())
      throw Error(ErrorCode::Schema, "an embedding's orbit type has no `_`", where);
    for (int x : d.orbit.dims())
      if (x < 0 || x > s.dimension)
        throw Error(ErrorCode::Schema,
                    "orbit type " + d.orbit.str() + " outside 0.." + std::to_string(s.dimension),
                    where);
    for (const auto& o : out)
      if (o.name == d.name) throw Error(ErrorCode::Schema, "embedding declared twice", where);
    out.push_back({d.name, d.orbit, *t});
  }
  return out;
}

CheckContext check_context(const scheme::RuleScheme& s,
                           const std::vector<EmbeddingSignature>& sigs) {
  CheckContext c;
  c.dimension = s.dimension;
  for (const auto& n : s.left.nodes) c.nodes.push_back(n.name);
  for (uint32_t v = 0; v < s.right.size(); ++v)
    if (!s.left_of(v)) c.right_only.push_back(s.right.nodes[v].name);
  c.embeddings = sigs;
  return c;
}

std::shared_ptr<const Expr> compile_expression(const std::string& code,
                                               const EmbeddingSignature& sig, CheckContext ctx,
                                               const std::string& where) {
  auto e = parse_expression(code, where);
  ctx.where = where;
  check_expression(*e, ctx, sig.type);
  return std::shared_ptr<const Expr>(std::move(e));
}

CompiledScheme compile_scheme(const scheme::RuleScheme& s) {
  CompiledScheme cs;
  cs.scheme = &s;
  cs.embeddings = embedding_signatures(s);
  const CheckContext ctx = check_context(s, cs.embeddings);
  cs.right.assign(cs.embeddings.size(), std::vector<std::shared_ptr<const Expr>>(s.right.size()));
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    for (const auto& x : s.right.nodes[v].expressions) {
      if (x.code.empty() && !x.unsupported.empty()) continue;  // an untranslated Jerboa expression
      const std::string where =
          "rule " + s.name + ", R node " + s.right.nodes[v].name + ", embedding " + x.embedding;
      size_t k = 0;
      while (k < cs.embeddings.size() && cs.embeddings[k].name != x.embedding) ++k;
      if (k == cs.embeddings.size())
        throw Error(ErrorCode::Schema,
                    "the embedding '" + x.embedding + "' is not declared by the rule", where);
      if (cs.right[k][v])
        throw Error(ErrorCode::Schema,
                    "two expressions for one embedding on one node (thesis Def. 71, uniqueness)",
                    where);
      cs.right[k][v] = compile_expression(x.code, cs.embeddings[k], ctx, where);
    }
  }
  for (uint32_t v = 0; v < s.left.size(); ++v)
    if (!s.left.nodes[v].expressions.empty() && !s.right_of(v))
      throw Error(ErrorCode::Schema,
                  "an expression on a deleted node (expressions belong to right nodes)",
                  "rule " + s.name + ", L node " + s.left.nodes[v].name);
  return cs;
}

}  // namespace gmr::expr
