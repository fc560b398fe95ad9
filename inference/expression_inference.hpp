// Inference of affine embedding expressions from a before/after pair (thesis Ch. 8, §8.2).
//
// Input: a topological rule scheme S (e.g. from topological folding), the object before G and the
// object after H with positions, and the hook dart(s): S is applied to a copy of G (the scheme
// engine numbers the new darts deterministically), which must give H's links exactly, so that the
// engine's match and comatch tables associate every R node and orbit dart with a dart of H
// (thesis §8.2: "the associated darts").
// For every right node n_r whose positions are not all kept (§8.2.3 step 1: a preserved node
// whose after value equals its before value at every orbit dart gets no expression, and its whole
// <o_pi>-class of R is solved), the affine model of Eq. 8.2 is fitted:
//     pos(n_r) = sum over L classes (one representative n_l each) and points of interest p of
//                w[p][n_l] * p(n_l)  +  t,
// with the points of interest the barycentres of the collects <>, <0>, <0,1>, ..., <0..n> of the
// position (vertex, edge, face, volume, connected component: Table 8.1's representatives), one
// vector equation per orbit dart. The system is solved exactly over the rationals (GMP): the
// doubles of G and H are first read as the simplest rationals within 1e-9 (denominators up to
// 10^6), so that 1/3 stored as 0.333... is 1/3. Among the solutions the sparsest is chosen by
// trying supports of 1, 2, then 3 weights in the order of the points of interest (v, e, f, s, cc)
// and L classes, without then with the translation; the report says whether the solution is
// unique (the system's rank equals its number of unknowns) and names nodes without solution.
// Decision where the thesis is silent (its solver's "additional constraints"): this sparsest-first
// order; the thesis' OR-tools answer may differ when the solution is not unique.
#pragma once
#include <string>
#include <vector>

#include "model/core/embedded_map.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::inference {

struct InferredExpression {
  std::string node;  // R node name
  enum class Status { Kept, Solved, Inherited, NoSolution } status = Status::NoSolution;
  std::string code;     // the expression (Solved)
  bool unique = false;  // Solved: the only solution of the system
  size_t rank = 0, unknowns = 0, equations = 0;
};

struct ExpressionInference {
  std::vector<InferredExpression> nodes;  // one per right node, in order
  // The scheme with the inferred expressions written on its right nodes (and the declaration).
  scheme::RuleScheme scheme;
};

// `embedding` names the positions (a point embedding on <1..n>). Throws gmr::Error(Usage) when
// the scheme does not apply at `hooks` or its result differs from `after`.
ExpressionInference infer_expressions(const scheme::RuleScheme& s, const EmbeddedMap& before,
                                      const std::vector<Dart>& hooks, const EmbeddedMap& after,
                                      const std::string& embedding = "position");

}  // namespace gmr::inference
