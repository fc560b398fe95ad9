#include "model/words/pattern_graph.hpp"

#include <algorithm>
#include <deque>
#include <string>

#include "model/core/error.hpp"

namespace gmr::words {
using namespace gmr::graph;

int PatternGraph::label_of(const PathWord& w) const {
  for (size_t k = 0; k < words.size(); ++k)
    if (words[k] == w) return static_cast<int>(k);
  return -1;
}

std::vector<Node> PatternGraph::targets(Node v, const PathWord& w) const {
  const int l = label_of(w);
  if (l < 0) return {};
  return graph.successors(v, l);
}

Node follow_word(const DGraph& G, Node v, const PathWord& w) {
  for (const Letter& l : w) {
    const auto next = l.conj ? G.predecessors(v, l.dim) : G.successors(v, l.dim);
    if (next.size() != 1)
      throw Error(ErrorCode::InvalidMap,
                  "incident arcs fails: " + std::to_string(next.size()) +
                      (l.conj ? " incoming " : " outgoing ") + std::to_string(l.dim) +
                      "-arcs while following the word " + to_string(w),
                  "node " + G.node_str(v));
    v = next[0];
  }
  return v;
}

PatternGraph pattern_graph(const DGraph& G, const std::vector<PathWord>& W) {
  PatternGraph P;
  for (const PathWord& w : W)
    if (std::find(P.words.begin(), P.words.end(), w) == P.words.end()) P.words.push_back(w);
  for (Node v : G.nodes()) {
    P.graph.add_node(G.name(v));
    P.origin.push_back(v);
  }
  for (Node v : G.nodes())
    for (size_t k = 0; k < P.words.size(); ++k)
      P.graph.add_arc(v, follow_word(G, v, P.words[k]), static_cast<int>(k));
  return P;
}

PatternGraph pattern_graph(const Map& g, const std::vector<PathWord>& W) {
  return pattern_graph(to_dgraph(g), W);
}

namespace {
std::vector<Node> bfs(const DGraph& g, Node v, HandleVector<Node, bool>& seen) {
  std::vector<Node> order{v};
  seen[v] = true;
  for (size_t k = 0; k < order.size(); ++k) {
    const Node x = order[k];
    auto visit = [&](Node y) {
      if (!seen[y]) {
        seen[y] = true;
        order.push_back(y);
      }
    };
    for (ArcId a : g.out_arcs(x))
      if (g.arc_alive(a)) visit(g.arc(a).tgt);
    for (ArcId a : g.in_arcs(x))
      if (g.arc_alive(a)) visit(g.arc(a).src);
  }
  return order;
}
}  // namespace

PatternGraph component(const PatternGraph& P, Node v) {
  if (v.index() >= P.size())
    throw Error(ErrorCode::Range, "no node " + std::to_string(v.index()) + " in the pattern graph",
                "P_v");
  HandleVector<Node, bool> seen(P.size(), false);
  const std::vector<Node> order = bfs(P.graph, v, seen);
  HandleVector<Node, Node> index(P.size());
  PatternGraph out;
  out.words = P.words;
  for (size_t k = 0; k < order.size(); ++k) {
    index[order[k]] = Node(static_cast<uint32_t>(k));
    out.graph.add_node(P.graph.name(order[k]));
    out.origin.push_back(P.origin[order[k]]);
  }
  for (Node x : order)
    for (ArcId a : P.graph.out_arcs(x))
      if (P.graph.arc_alive(a))
        out.graph.add_arc(index[x], index[P.graph.arc(a).tgt], P.graph.arc(a).label);
  return out;
}

std::vector<std::vector<Node>> components(const PatternGraph& P) {
  HandleVector<Node, bool> seen(P.size(), false);
  std::vector<std::vector<Node>> out;
  for (Node v : P.graph.nodes()) {
    if (seen[v]) continue;
    auto c = bfs(P.graph, v, seen);
    std::sort(c.begin(), c.end());
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace gmr::words
