// The permutations of a small dart set {0, ..., k-1} from which the exhaustive enumerations of
// small maps (map_family.hpp) and of the hook orbits of the scheme verifier
// (checker/smt/scheme_verifier.hpp) assemble their alpha_i.
#pragma once
#include <vector>

#include "model/core/map.hpp"

namespace gmr::graph {

// p[x] is the image of dart x.
using DartPermutation = std::vector<Dart>;

// Every involution of k darts (fixed points allowed), each once.
std::vector<DartPermutation> involutions(size_t k);

// Every permutation of k darts, in lexicographic order.
std::vector<DartPermutation> permutations(size_t k);

// The cycle constraint C(i,j) of a pair of labels (MapSpec cycle pairs, Defs. 31-32): a b a b is
// the identity.
bool commute(const DartPermutation& a, const DartPermutation& b);

// Whether the k darts form one orbit of the group the permutations `s` generate.
bool connected(const std::vector<const DartPermutation*>& s, size_t k);

}  // namespace gmr::graph
