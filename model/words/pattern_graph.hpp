// Pattern graphs and the pattern functor (thesis §4.2, Defs. 42, 48, Fact 2).
//
// A pattern graph is a W-graph: arcs labelled by words of W ⊆ D̄*. It is stored as a DGraph whose
// int labels index the word list `words` (label k = words[k]).
//
// Pattern functor P_(D,W) (Def. 48) on a D-combinatorial graph G: same nodes (and names); for every
// node v and every w ∈ W, one w-arc v -> t_w(v), where t_w(v) is the end of the unique w-path
// from v (Fact 2): a letter d follows the d-arc leaving the current node, a conjugated letter ~d
// follows a d-arc backwards (the reversed arc of the conjugate graph Ḡ). ε ends where it starts,
// so ε ∈ W gives an ε-loop on every node. Only the dimensions occurring in W are read: the other
// arcs of G (e.g. the 3-arcs of F8) are dropped, and G needs incident arcs I_G only on those.
//
// P_v (§4.2): the maximal subgraph containing v closed under incident arcs, i.e. the weakly
// connected component of v ("strongly connected" in Ex. 48 agrees only when
// O_P(W) holds).
#pragma once
#include <optional>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/dgraph.hpp"
#include "model/words/word_rewriting.hpp"

namespace gmr::words {
using graph::DGraph;
using graph::Node;

struct PatternGraph {
  DGraph graph;                     // label k = words[k]
  std::vector<PathWord> words;      // W, without duplicates
  HandleVector<Node, Node> origin;  // node of P -> node of the graph it was built from

  size_t size() const { return graph.num_nodes(); }
  // Label index of w, or -1 when w ∉ W.
  int label_of(const PathWord& w) const;
  // Targets of the w-arcs leaving v (exactly one in a pattern graph satisfying I_P(W)).
  std::vector<Node> targets(Node v, const PathWord& w) const;
};

// End of the w-path from v (Fact 2). Throws Error(InvalidMap) naming the node and letter when the
// step is not unique (G does not satisfy I_G on that dimension).
Node follow_word(const DGraph& G, Node v, const PathWord& w);

// P_(D,W)(G). Duplicate words of W are ignored.
PatternGraph pattern_graph(const DGraph& G, const std::vector<PathWord>& W);
// On a map: through to_dgraph (node k = k-th live dart, named by the dart index).
PatternGraph pattern_graph(const Map& g, const std::vector<PathWord>& W);

// P_v: the component of v, nodes in BFS order (v first), names and `origin` carried over (origin
// composes with the one of P).
PatternGraph component(const PatternGraph& P, Node v);
// The components of P as node sets (each sorted), ordered by smallest node.
std::vector<std::vector<Node>> components(const PatternGraph& P);

}  // namespace gmr::words
