#include "checker/events/concrete_scheme.hpp"

#include "model/core/error.hpp"

namespace gmr::events {
using graph::DGraph;
using scheme::GraphScheme;

namespace {

// The nodes (label <>) and the explicit arcs of one side: an arc a -i-> b stands for the link when
// a <= b, or when the D-graph lacks its reverse b -i-> a.
GraphScheme side_of(const DGraph& d) {
  GraphScheme g;
  for (graph::Node v : d.nodes()) g.add_node(d.name(v), OrbitType{});
  for (graph::ArcId a : d.arc_slots()) {
    if (!d.arc_alive(a)) continue;
    const graph::Arc& e = d.arc(a);
    if (e.src > e.tgt) {
      bool reverse = false;
      for (graph::Node w : d.successors(e.tgt, e.label)) reverse = reverse || w == e.src;
      if (reverse) continue;
    }
    g.arcs.push_back({e.src.index(), e.tgt.index(), e.label});  // scheme node k is node k of d
  }
  return g;
}

}  // namespace

scheme::RuleScheme scheme_of_concrete_rule(const rewrite::Rule& r) {
  if (r.kind() != MapKind::GMap)
    throw Error(ErrorCode::Usage,
                "rule schemes (and their events) rewrite G-maps; this rule rewrites O-maps",
                "rule " + r.name());
  scheme::RuleScheme s;
  s.name = r.name();
  s.description = "The concrete rule " + r.name() + " as a rule scheme on <> (one dart per node).";
  s.dimension = r.dimension();
  s.orbit = OrbitType{};
  s.left = side_of(r.left());
  s.right = side_of(r.right());
  std::vector<uint32_t> comp;
  const size_t nc = s.left.components(comp);
  std::vector<bool> has_hook(nc, false);
  for (uint32_t v = 0; v < s.left.size(); ++v)
    if (!has_hook[comp[v]]) {
      has_hook[comp[v]] = true;
      s.hooks.push_back(s.left.nodes[v].name);
    }
  s.validate_structure();
  return s;
}

}  // namespace gmr::events
