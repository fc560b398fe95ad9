// Generated families of small concrete rules, for the empirical equivalence between the static
// checker and the semantic verdict, reusable by property-based tests.
//
//  * `for_each_small_rule`: EVERY rule over at most `max_nodes` nodes (named a, b, c) in L ∪ R,
//    each node preserved, deleted or added (status tuples taken in nondecreasing order to skip
//    the obvious renamings), whose L and R have, for every label of `arc_labels`, a partial
//    injection as i-arcs (at most one outgoing and one incoming i-arc per node: loops, single
//    arcs, 2-cycles ...). Labels of the model outside `arc_labels` carry no arcs. R is not forced
//    to satisfy anything else, so the family mixes consistent and inconsistent rules.
//    Size: with k labels and 2 preserved nodes, 7^(2k) rules.
//  * `random_rule_from_maps`: a larger random rule whose L is an induced subgraph of a map of the
//    family (so that it is applicable) with a few arcs dropped, some nodes deleted, and whose R is
//    an induced subgraph of another map of the family around the preserved nodes plus up to two
//    added nodes, again with a few arcs dropped or toggled.
#pragma once
#include <functional>
#include <random>
#include <vector>

#include "model/graph/map_family.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::testing {
using graph::MapFamily;
using rewrite::Rule;

size_t for_each_small_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& arc_labels,
                           const std::function<bool(const Rule&)>& f);

Rule random_rule_from_maps(std::mt19937_64& rng, const MapFamily& family,
                           size_t max_left_nodes = 4);

// One random member of the `for_each_small_rule` family (property tests): up to max_nodes nodes,
// each preserved, deleted or added, and for every label of the model a random partial injection
// as i-arcs of L and of R. Drawn with the portable `uniform` (random_maps.hpp).
Rule random_small_rule(std::mt19937_64& rng, int n, MapKind kind, int max_nodes = 3);

// A rule consistent by construction: L is a whole map of the family (every node has every label:
// a complete G-map, resp. O-map), R another whole map; the first p nodes of R take the names of
// the first p nodes of L (preserved), the other L nodes are deleted and the other R nodes added.
// It matches exactly the isolated components isomorphic to L and replaces them by R, so it
// preserves the model and the checker must accept it (property concrete_valid_accepted).
Rule component_replacement_rule(std::mt19937_64& rng, const MapFamily& family);

}  // namespace gmr::testing
