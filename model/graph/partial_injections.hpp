// The partial injections of the nodes {0, ..., m-1} into themselves: the possible sets of arcs of
// one label among m nodes (at most one arc leaving and one arc entering each node), from which the
// exhaustive families of small rules are assembled (model/testing/rule_family.hpp,
// checker/smt/rule_space.hpp).
#pragma once
#include <utility>
#include <vector>

#include "model/graph/dgraph.hpp"

namespace gmr::graph {

// (source, target) pairs, sources increasing.
using PartialInjection = std::vector<std::pair<Node, Node>>;

// Every partial injection of m nodes, each once (the empty one first).
std::vector<PartialInjection> partial_injections(size_t m);

}  // namespace gmr::graph
