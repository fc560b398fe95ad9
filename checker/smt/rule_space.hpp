// The bounded family of concrete rules a condition is validated on (`gmr validate-condition`,
// condition_validation.hpp): EVERY rule over 1..max_nodes nodes (named a, b, c, ...), each node
// preserved, deleted or added (status tuples in nondecreasing order: renamings skipped), whose L
// and R have, for every label of `labels`, a partial injection as i-arcs (at most one outgoing
// and one incoming i-arc per node: loops, single arcs, 2-cycles, ...). Labels of the model outside
// `labels` carry no arcs. Rules come in increasing number of nodes, so the first counterexample
// has the fewest nodes. Size: with k labels and m preserved nodes, (P(m)^2)^k rules, P(1) = 2,
// P(2) = 7, P(3) = 34 partial injections.
#pragma once
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "model/rewrite/rule.hpp"

namespace gmr::smt {

// Calls f(index, rule) for every rule; f returns false to stop. Returns the number visited.
size_t for_each_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& labels,
                     const std::function<bool(size_t, const rewrite::Rule&)>& f);
// The number of rules of the family with exactly `nodes` nodes (without building them).
size_t count_rules(int nodes, size_t labels);

// The rule in one line: "L {a b; a-0->b} => R {a b; b-0->a}" (node names; arcs
// source-label->target).
std::string rule_text(const rewrite::Rule& r);

// One random rule of exactly `nodes` nodes in the same shape (each node preserved, deleted or
// added uniformly; per label a uniformly drawn partial injection on each side), named `name`.
// Deterministic for a given generator state (std::mt19937_64, portable draws).
rewrite::Rule random_rule(std::mt19937_64& rng, int n, MapKind kind, int nodes,
                          const std::vector<int>& labels, const std::string& name);

}  // namespace gmr::smt
