// Embedding expressions (docs/embeddings.md): parse, within the length and nesting limits.
#include "model/expr/parser.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const auto e = expr::parse_expression(text, "fuzz");
  if (!e) __builtin_trap();  // a parse either succeeds with a tree or throws
}
