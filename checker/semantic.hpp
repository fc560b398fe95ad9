// Enumeration engine and semantic verdicts (issue 3; reused by the SMT and property-based work).
//
//  * `connected_maps(n, kind, k)`: every connected n-G-map (labels 0..n, all involutions,
//    C(i,j) for i+2 <= j) or n-O-map (beta_1 any permutation, beta_2..n involutions,
//    C on (1..n)_{+2}) with exactly k darts, one per isomorphism class (canonical dedup by
//    the BFS-word signature of signature.hpp). Brute force over the involutions/permutations of
//    k darts: meant for k <= 6 (n <= 2) — larger sizes grow as (#involutions(k))^(n+1).
//  * `map_family(n, kind, max_darts)`: every map with 1..max_darts darts up to isomorphism, i.e.
//    the multisets of connected classes of total size <= max_darts, sorted by size (so the first
//    counterexample found is a smallest one), with their D-graphs.
//  * `semantic_verdict(rule, family)`: applies the rule through EVERY match (injective,
//    label-preserving) satisfying the gluing condition on every map of the family and checks that
//    the result is a G-map (resp. O-map) of the same dimension (Def. 32, check_gmap_constraints).
//    `applications == 0` means the rule is not applicable within the bound (no match, or no match
//    satisfies the gluing condition): its verdict is then vacuously "preserves" — callers that
//    compare with the static checker must treat such rules separately (see the equivalence test).
//  * `per_constraint`: also records which constraint kinds (I, O, C with dims) were broken, for
//    per-condition comparisons.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/constraints.hpp"
#include "model/dgraph.hpp"
#include "model/gmap.hpp"
#include "model/match.hpp"
#include "model/rule.hpp"

namespace gmr {

std::vector<GMap> connected_maps(int n, MapKind kind, size_t darts);

struct MapFamily {
  int n = 0;
  MapKind kind = MapKind::GMap;
  size_t max_darts = 0;
  std::vector<GMap> maps;
  std::vector<DGraph> graphs;  // to_dgraph(maps[k])
};
MapFamily map_family(int n, MapKind kind, size_t max_darts);

struct SemanticWitness {
  size_t map_index = 0;
  Match match;
  DGraph H;
  std::vector<ConstraintViolation> violations;
  std::string describe(const Rule& r, const MapFamily& f) const;
};

struct SemanticVerdict {
  size_t matches = 0;       // matches found (gluing or not)
  size_t applications = 0;  // matches satisfying the gluing condition
  bool preserves = true;    // every application yields a map of the model
  std::optional<SemanticWitness> witness;  // the first breaking application (smallest map first)
  bool applicable() const { return applications > 0; }
};

// stop_at_first: return at the first breaking application (the default).
SemanticVerdict semantic_verdict(const Rule& r, const MapFamily& f, bool stop_at_first = true);

}  // namespace gmr
