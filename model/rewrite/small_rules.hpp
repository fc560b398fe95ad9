// The bounded family of small concrete rules on which conditions are validated exhaustively
// (checker/smt/rule_space.hpp, model/testing/rule_family.hpp): EVERY rule over 1..max_nodes nodes
// (named a, b, c, ...), each node preserved, deleted or added (status tuples in nondecreasing
// order: renamings skipped), whose L and R have, for every label of `labels`, a partial injection
// as i-arcs (graph/partial_injections.hpp). Labels of the model outside `labels` carry no arcs.
// Rules come in increasing number of nodes, so the first counterexample has the fewest nodes.
#pragma once
#include <functional>
#include <vector>

#include "model/rewrite/rule.hpp"

namespace gmr::rewrite {

// Calls f(st) for every status tuple of `nodes` nodes (0 preserved, 1 deleted, 2 added), in
// nondecreasing order.
void for_each_status_tuple(size_t nodes, const std::function<void(const std::vector<int>&)>& f);

// Calls f(index, rule) for every rule of the family, the rule named "rule<index>"; f returns false
// to stop. Returns the number visited.
size_t for_each_small_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& labels,
                           const std::function<bool(size_t, const Rule&)>& f);

}  // namespace gmr::rewrite
