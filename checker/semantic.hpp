// Semantic verdicts of concrete rules on the bounded family of small maps
// (model/graph/map_family.hpp): the reference the static checker and the SMT encodings are compared
// with.
//
//  * `semantic_verdict(rule, family)`: applies the rule through EVERY match (injective,
//    label-preserving) satisfying the gluing condition on every map of the family and checks that
//    the result is a G-map (resp. O-map) of the same dimension (Def. 32, check_map_constraints).
//    `applications == 0` means the rule is not applicable within the bound (no match, or no match
//    satisfies the gluing condition): its verdict is then vacuously "preserves" — callers that
//    compare with the static checker must treat such rules separately (see the equivalence test).
//  * `per_constraint`: also records which constraint kinds (I, O, C with dims) were broken, for
//    per-condition comparisons.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/constraints.hpp"
#include "model/graph/dgraph.hpp"
#include "model/graph/map_family.hpp"
#include "model/rewrite/match.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::checker {
using graph::DGraph;
using graph::MapFamily;
using rewrite::Match;
using rewrite::Rule;

struct SemanticWitness {
  size_t map_index = 0;
  Match match;
  DGraph H;
  std::vector<ConstraintViolation> violations;  // of H (check_map_constraints)
};

struct SemanticVerdict {
  size_t matches = 0;                      // matches found (gluing or not)
  size_t applications = 0;                 // matches satisfying the gluing condition
  bool preserves = true;                   // every application yields a map of the model
  std::optional<SemanticWitness> witness;  // the first breaking application (smallest map first)
  bool applicable() const { return applications > 0; }
};

// stop_at_first: return at the first breaking application (the default).
SemanticVerdict semantic_verdict(const Rule& r, const MapFamily& f, bool stop_at_first = true);

}  // namespace gmr::checker
