// Static embedding checks of rule schemes (thesis Ch. 5: Defs. 71, 74, 81; §5.5; Jerboa §6.3.3),
// run by the scheme checker (scheme_checker.hpp) when the scheme declares embeddings or carries
// expressions. Classes are computed per embedding pi over the explicit arcs of R whose dimension
// is in <o_pi> (node labels are ignored, §6.3.3): within a scheme every instance of a class is one
// orbit piece of the result. Codes (severity error unless marked):
//   E-declaration   an embedding declaration with an unknown value type, `_` or a dimension
//                   outside 0..n in its orbit type, or declared twice
//   E-undeclared    an expression for an embedding the scheme does not declare
//   E-unique        two expressions for one embedding on one node (Def. 71, uniqueness)
//   E-expression    an expression that does not parse or type-check (the message names the column;
//                   types in docs/embeddings.md)
//   E-orbit-terms   two nodes of one class with syntactically different expressions (Def. 71,
//                   orbit consistency; Fig. 5.15a). Syntactic: equal values written differently are
//                   rejected (the thesis compares terms, §5.6)
//   E-no-value      a class of added nodes only and no expression: its orbits get no value
//                   (Def. 81, all-or-nothing; Fig. 5.15b)
//   E-merge         a class without expression whose preserved nodes lie in different classes of
//                   L: the rewrite merges orbits that may hold different values (Fig. 5.18a)
//   E-unsupported   (warning) a Jerboa expression that could not be translated
//   (model/rule_io/jme_expression.hpp);
//                   the node is checked as if it had none
//   E-merge-instances (warning) a preserved node without expression whose R label links, for pi,
//                   positions its L label does not: the instances of the node may merge several
//                   L orbits (whether their values agree depends on the match)
// The overlap condition (Def. 84, Lemma 12) depends on the match: it is checked at application
// time (model/expr/propagation.hpp, E-overlap).
#pragma once
#include <vector>

#include "checker/diagnostic.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::checker {

// Appends the diagnostics; returns true when none is an error.
bool check_embeddings(const scheme::RuleScheme& s, std::vector<Diagnostic>& out);

}  // namespace gmr::checker
