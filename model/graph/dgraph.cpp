#include "model/graph/dgraph.hpp"

#include "model/core/error.hpp"

namespace gmr::graph {

Node DGraph::add_node(std::string name) {
  names_.push_back(std::move(name));
  out_.emplace_back();
  in_.emplace_back();
  return Node(static_cast<uint32_t>(names_.size() - 1));
}

ArcId DGraph::add_arc(Node src, Node tgt, int label) {
  if (src.index() >= num_nodes() || tgt.index() >= num_nodes())
    throw Error(ErrorCode::Range, "arc between unknown nodes " + std::to_string(src.index()) +
                                      " and " + std::to_string(tgt.index()));
  const ArcId id(static_cast<uint32_t>(arcs_.size()));
  arcs_.push_back({src, tgt, label});
  arc_alive_.push_back(true);
  out_[src].push_back(id);
  in_[tgt].push_back(id);
  return id;
}

void DGraph::add_link(Node a, Node b, int label) {
  add_arc(a, b, label);
  if (a != b) add_arc(b, a, label);
}

void DGraph::remove_arc(ArcId a) {
  if (!arc_alive_[a]) return;
  arc_alive_[a] = false;
  auto erase = [a](std::vector<ArcId>& v) {
    for (size_t k = 0; k < v.size(); ++k)
      if (v[k] == a) {
        v.erase(v.begin() + static_cast<long>(k));
        return;
      }
  };
  erase(out_[arcs_[a].src]);
  erase(in_[arcs_[a].tgt]);
}

size_t DGraph::num_arcs() const {
  size_t n = 0;
  for (bool b : arc_alive_) n += b;
  return n;
}

std::optional<Node> DGraph::find(const std::string& name) const {
  for (Node v : nodes())
    if (names_[v] == name) return v;
  return std::nullopt;
}

std::string DGraph::node_str(Node v) const {
  return names_[v].empty() ? "#" + std::to_string(v.index()) : names_[v];
}

std::vector<Node> DGraph::successors(Node v, int label) const {
  std::vector<Node> out;
  for (ArcId a : out_[v])
    if (arcs_[a].label == label) out.push_back(arcs_[a].tgt);
  return out;
}

std::vector<Node> DGraph::predecessors(Node v, int label) const {
  std::vector<Node> out;
  for (ArcId a : in_[v])
    if (arcs_[a].label == label) out.push_back(arcs_[a].src);
  return out;
}

DGraph to_dgraph(const Map& g) {
  DGraph dg;
  std::vector<Node> node_of(g.capacity());
  g.for_each_dart([&](Dart d) { node_of[d] = dg.add_node(std::to_string(d)); });
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    g.for_each_dart([&](Dart d) {
      const Dart e = g.alpha(i, d);
      if (g.alive(e)) dg.add_arc(node_of[d], node_of[e], i);
    });
  }
  return dg;
}

Map to_map(const DGraph& dg, int n, MapKind kind) {
  Map g(n, kind);
  g.add_darts(dg.num_nodes());
  for (Node v : dg.nodes()) {
    for (int i = g.lowest_dim(); i <= n; ++i) {
      const auto succ = dg.successors(v, i);
      if (succ.size() != 1)
        throw Error(ErrorCode::InvalidMap,
                    "incident arcs I(" + std::to_string(i) + ") fails: node has " +
                        std::to_string(succ.size()) + " outgoing " + std::to_string(i) + "-arcs",
                    "node " + dg.node_str(v));
      g.set_alpha(i, dart_of(v), dart_of(succ[0]));
    }
  }
  for (ArcId a : dg.arc_slots())
    if (dg.arc_alive(a) && !g.has_dim(dg.arc(a).label))
      throw Error(ErrorCode::Range,
                  "label " + std::to_string(dg.arc(a).label) + " outside the map's dimensions",
                  "arc " + dg.node_str(dg.arc(a).src) + " -> " + dg.node_str(dg.arc(a).tgt));
  return g;
}

}  // namespace gmr::graph
