// Instantiation of Jerboa rule schemes on an orbit graph (thesis Defs. 88–89; inference paper
// Defs. 4.3–4.6).
//
// The orbit graph O of a scheme of parameter <o> has darts b = 0..s-1 and, for each position p of
// <o>, a link b –o[p]– nb(b,p) (an involution on the darts; a fixed point is a loop).
//  * node (Def. 88): ι(v,O) = [<o> ↦ <o^v>](O): one node (u,v) per dart u, written "u_v", and
//    (u,v) –o^v[p]– (nb(u,p),v) for every position p with o^v[p] != `_`;
//  * discrete scheme: the union of the node instantiations;
//  * arc (Def. 89): ι(s –i– t, O) = ⋃_u (u,s) –i– (u,t);
//  * scheme: nodes and arcs; rule: L and R instantiated on the same O, preserved instantiated nodes
//    sharing their name "u_v".
// The result is a D-graph (arcs directed, a link between distinct nodes = two opposite arcs, a loop
// = one arc, as in to_dgraph) and a table (scheme node, orbit dart) -> instantiated node.
#pragma once
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::scheme {
using graph::DGraph;
using graph::Node;
using rewrite::Rule;

struct OrbitGraph {
  size_t arity = 0;          // |<o>|
  std::vector<Dart> darts;   // darts[b]: the dart of G standing for b (used in names "u_v")
  std::vector<uint32_t> nb;  // nb[b * arity + p]
  size_t size() const { return darts.size(); }
  uint32_t neighbor(uint32_t b, size_t p) const { return nb[b * arity + p]; }
};

// The <t>-orbit of d in g (Algorithm 4, BFS), its darts indexed in BFS order (d gets 0), position p
// of the orbit graph following dimension t[p]. `t` has no `_`. Throws Error(Range) for a dead dart
// or a dimension the map lacks.
OrbitGraph orbit_graph(const Map& g, const OrbitType& t, Dart d);
// One abstract dart, free at every position (the orbit used when L has no hook).
OrbitGraph single_dart_orbit(size_t arity);

struct InstantiatedGraph {
  DGraph graph;
  size_t orbit_size = 0;
  std::vector<Node> table;  // table[v * orbit_size + b]
  Node at(uint32_t v, uint32_t b) const { return table[v * orbit_size + b]; }
};

// "u_v" with u the dart of G (O.darts[b]) and v the node name.
std::string instance_name(const OrbitGraph& O, uint32_t b, const std::string& node);

// Def. 88: one node. Throws Error(Schema) when the label's arity differs from O's.
InstantiatedGraph instantiate_node(const SchemeNode& v, const OrbitGraph& O);
// Discrete scheme (all nodes, no explicit arcs).
InstantiatedGraph instantiate_nodes(const GraphScheme& s, const OrbitGraph& O);
// Def. 89: adds the instances of one explicit arc to an instantiation of the nodes.
void instantiate_arc(const SchemeArc& e, const OrbitGraph& O, InstantiatedGraph& into);
// Whole graph scheme.
InstantiatedGraph instantiate_graph(const GraphScheme& s, const OrbitGraph& O);

struct InstantiatedRule {
  InstantiatedGraph left, right;
};
InstantiatedRule instantiate_sides(const RuleScheme& r, const OrbitGraph& O);
// The instantiated rule as a concrete DPO rule (model/rewrite/rule.hpp): L and R with the names
// "u_v", preserved instances sharing names, arcs deduced by Assumption 4. The concrete L node of
// (scheme node v, orbit dart b) has index v * |O| + b (same for R).
Rule instantiate_rule(const RuleScheme& r, const OrbitGraph& O);

// The orbit graph a scheme is instantiated on when applied at `hook_dart` (reference hook): the
// orbit of the reference hook's label, positions in the order of that label (so that position p
// stands for o[p]). For a scheme with no hook, single_dart_orbit.
OrbitGraph hook_orbit_graph(const Map& g, const RuleScheme& r, Dart hook_dart);

}  // namespace gmr::scheme
