// D-graphs: directed arc-labelled multigraphs (thesis §3.1, "topological graphs"), loops and
// parallel arcs allowed. Labels are dimensions. This is the general carrier of the DPO rewriting
// and of the three local constraints; a Map is the compact form of a D-graph that satisfies
// incident arcs (one outgoing arc per label) and is convertible both ways.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/core/handle.hpp"
#include "model/core/map.hpp"

namespace gmr::graph {

// Nodes and arcs are named by distinct handles (model/core/handle.hpp): a node, an arc and a dart
// (Map's uint32_t) cannot be passed for one another.
using Node = Handle<struct NodeTag>;
using ArcId = Handle<struct ArcTag>;
inline constexpr Node kNoNode = Node::none();
inline constexpr ArcId kNoArc = ArcId::none();

struct Arc {
  Node src;
  Node tgt;
  int label;
};

class DGraph {
 public:
  DGraph() = default;

  Node add_node(std::string name = {});
  // Adds the arc src -i-> tgt. Throws Error(Range) for unknown nodes.
  ArcId add_arc(Node src, Node tgt, int label);
  // Adds src -i-> tgt and, unless src == tgt (a loop is its own reverse), tgt -i-> src.
  void add_link(Node a, Node b, int label);
  void remove_arc(ArcId a);  // arcs are tombstoned; ids of other arcs stay valid
  bool arc_alive(ArcId a) const { return arc_alive_[a]; }
  // Every node; every arc slot (dead ones included).
  HandleRange<Node> nodes() const { return names_.handles(); }
  HandleRange<ArcId> arc_slots() const { return arcs_.handles(); }

  size_t num_nodes() const { return names_.size(); }
  size_t num_arc_slots() const { return arcs_.size(); }
  size_t num_arcs() const;
  const Arc& arc(ArcId a) const { return arcs_[a]; }
  const std::string& name(Node v) const { return names_[v]; }
  std::optional<Node> find(const std::string& name) const;
  std::string node_str(Node v) const;  // the name, or "#v"

  const std::vector<ArcId>& out_arcs(Node v) const { return out_[v]; }
  const std::vector<ArcId>& in_arcs(Node v) const { return in_[v]; }
  // Targets of the live i-arcs leaving v.
  std::vector<Node> successors(Node v, int label) const;
  std::vector<Node> predecessors(Node v, int label) const;

 private:
  HandleVector<Node, std::string> names_;
  HandleVector<ArcId, Arc> arcs_;
  HandleVector<ArcId, bool> arc_alive_;
  HandleVector<Node, std::vector<ArcId>> out_, in_;
};

// G-map <-> D-graph. Each dart becomes a node named by its index; an i-link between distinct darts
// becomes two opposite i-arcs, an i-loop one loop arc.
DGraph to_dgraph(const Map& g);
// The correspondence of to_dgraph and to_map on a map whose darts are 0..size-1 (no free slot):
// node v of the D-graph is dart v of the map.
inline Node node_of(Dart d) { return Node(d); }
inline Dart dart_of(Node v) { return v.index(); }
// Requires incident arcs on every label of the map (one outgoing i-arc per node); throws
// Error(InvalidMap) naming the node and label otherwise. Other constraints are not required.
Map to_map(const DGraph& dg, int n, MapKind kind = MapKind::GMap);

}  // namespace gmr::graph
