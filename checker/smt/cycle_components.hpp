// The cycle condition C_r as a conjunction over the connected components of a rule (docs/verify.md,
// "The cycle condition by components"; the argument is in proofs/README.md, "C_r by components").
//
// A component is a connected component of the rule's nodes (an L node and its R image are one
// node, identified by name) under the arcs of the cycle labels on either side. On a rule whose L
// and R are partial injections on the cycle labels and which satisfies w-I_r on them (Def. 33: a
// preserved node has an outgoing, resp. incoming, i-arc in L iff in R),
//
//     C_r(rule) = AND over the components K of C_r(rule restricted to K),
//
// in each reading of C_r (model completion, ij-completion, as written), and C_r of a component
// does not depend on the order or names of its nodes and arcs. So a verdict of the checker on one
// component is a verdict on every rule that has an isomorphic component, wherever its nodes are.
// The decomposition fails without w-I_r: a completion may then give a node two i-arcs on one side,
// and the checker skips the pair for the whole rule.
#pragma once
#include <string>
#include <vector>

#include "checker/smt/symbolic_validation.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {

// The components under the arcs of `labels` (both sides, both directions), each as the names of
// its nodes in order of first appearance (L nodes in L order, then the added nodes in R order);
// components ordered by their first node.
std::vector<std::vector<std::string>> rule_components(const rewrite::Rule& r,
                                                      const std::vector<int>& labels);

// The sub-rule on the named nodes: their statuses and their arcs on `labels` only (other labels'
// arcs dropped), nodes in the order of `nodes`.
rewrite::Rule restrict_rule(const rewrite::Rule& r, const std::vector<std::string>& nodes,
                            const std::vector<int>& labels);

// The labels of the model's cycle pairs (C_r reads the node statuses and these labels' arcs only).
std::vector<int> cycle_labels(const MapSpec& spec);

// AND over the components (under the cycle labels) of C_r of the component, in that reading:
// equal to cycle_condition(r, reading) on every rule with w-I_r on the cycle labels.
bool cycle_condition_by_components(const rewrite::Rule& r, CycleReading reading);

}  // namespace gmr::smt
