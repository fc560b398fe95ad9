// Matches of a rule's left-hand side (thesis Def. 24, Assumption 1): injective, label-preserving
// graph morphisms m: L -> G (on nodes and arcs).
//
//  * enumeration: every match of L in G, by backtracking over the nodes of L in a breadth-first
//    order (a node adjacent to an already mapped one only tries the neighbours of its image).
//    Between parallel arcs with the same ends and label, the arc component is chosen first-fit:
//    matches are enumerated up to that choice, which gives isomorphic derivations;
//  * anchored matching: from given L-node -> G-node pairs, the rest of the match is propagated
//    along the arcs of L (linear in |L| for combinatorial L and G: each i-arc is the unique one of
//    its label at its source, resp. target). Requires L combinatorial (Def. 35, second item) and
//    every node of L reachable from an anchor; violations are located Error(Usage).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "model/graph/dgraph.hpp"

namespace gmr::rewrite {
using graph::ArcId;
using graph::DGraph;
using graph::kNoArc;
using graph::kNoNode;
using graph::Node;

// A node map L -> G: the image of each L node (kNoNode: none yet).
using NodeMap = HandleVector<Node, Node>;

struct Match {
  NodeMap node;                    // L node -> G node
  HandleVector<ArcId, ArcId> arc;  // L arc slot -> G arc (kNoArc for dead slots of L)
};

// Completes a node map into a match (first-fit arcs). nullopt when the node map is not injective
// or an arc of L has no (free) image.
std::optional<Match> match_from_nodes(const DGraph& L, const DGraph& G, const NodeMap& nodes);

// Calls f on every match; f returns false to stop. Returns the number of matches visited.
size_t for_each_match(const DGraph& L, const DGraph& G, const std::function<bool(const Match&)>& f);
std::vector<Match> find_matches(const DGraph& L, const DGraph& G, size_t limit = SIZE_MAX);

// Anchored matching (see above). nullopt when the propagation fails (a missing arc, two L nodes on
// one G node, an anchor contradicting the propagation).
std::optional<Match> anchored_match(const DGraph& L, const DGraph& G,
                                    const std::vector<std::pair<Node, Node>>& anchors);

// Is L combinatorial in the sense of Def. 35 (at most one outgoing and one incoming arc per label
// at every node)? On failure, `where` receives "node a: 2 outgoing 0-arcs".
bool at_most_one_arc_per_label(const DGraph& g, std::string* where = nullptr);

}  // namespace gmr::rewrite
