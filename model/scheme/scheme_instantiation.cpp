#include "model/scheme/scheme_instantiation.hpp"

#include "model/core/dart_index.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::scheme {
using namespace gmr::rewrite;

OrbitGraph orbit_graph(const Map& g, const OrbitType& t, Dart d) {
  require_orbit_type(g, t);
  if (!g.alive(d)) throw Error(ErrorCode::Range, "no such dart", "dart " + std::to_string(d));
  OrbitGraph O;
  O.arity = t.size();
  {
    ScopedMarker m(g);
    O.darts.push_back(d);
    m.mark(d);
    for (size_t k = 0; k < O.darts.size(); ++k) {
      const Dart v = O.darts[k];
      for (int i : t.dims()) {
        const Dart w = g.alpha(i, v);
        if (!m.test(w)) {
          m.mark(w);
          O.darts.push_back(w);
        }
      }
    }
    for (Dart x : O.darts) m.unmark(x);
    m.set_clean();
  }
  DartIndex index(g.capacity(), O.darts.size());
  for (uint32_t b = 0; b < O.darts.size(); ++b) index.set(O.darts[b], b);
  O.nb.resize(O.darts.size() * O.arity);
  for (uint32_t b = 0; b < O.darts.size(); ++b)
    for (size_t p = 0; p < O.arity; ++p)
      O.nb[b * O.arity + p] = index.get(g.alpha(t[p], O.darts[b]));
  return O;
}

OrbitGraph single_dart_orbit(size_t arity) {
  OrbitGraph O;
  O.arity = arity;
  O.darts = {0};
  O.nb.assign(arity, 0u);
  return O;
}

std::string instance_name(const OrbitGraph& O, uint32_t b, const std::string& node) {
  return std::to_string(O.darts[b]) + "_" + node;
}

static void add_node_instances(InstantiatedGraph& ig, uint32_t v, const SchemeNode& node,
                               const OrbitGraph& O) {
  if (node.label.size() != O.arity)
    throw Error(ErrorCode::Schema,
                "label " + node.label.str() + " has arity " + std::to_string(node.label.size()) +
                    ", the orbit graph has " + std::to_string(O.arity),
                "node " + node.name);
  const size_t s = O.size();
  for (uint32_t b = 0; b < s; ++b)
    ig.table[v * s + b] = ig.graph.add_node(instance_name(O, b, node.name));
  for (uint32_t b = 0; b < s; ++b)
    for (size_t p = 0; p < O.arity; ++p) {
      const int j = node.label[p];
      if (j == OrbitType::kHole) continue;
      // Each directed arc once: (b,v) -> (nb,v); the reverse comes from nb's own turn (O's links
      // are involutions), a loop gives one arc.
      ig.graph.add_arc(ig.table[v * s + b], ig.table[v * s + O.neighbor(b, p)], j);
    }
}

InstantiatedGraph instantiate_node(const SchemeNode& v, const OrbitGraph& O) {
  InstantiatedGraph ig;
  ig.orbit_size = O.size();
  ig.table.resize(O.size());
  add_node_instances(ig, 0, v, O);
  return ig;
}

InstantiatedGraph instantiate_nodes(const GraphScheme& s, const OrbitGraph& O) {
  InstantiatedGraph ig;
  ig.orbit_size = O.size();
  ig.table.resize(O.size() * s.size());
  for (uint32_t v = 0; v < s.size(); ++v) add_node_instances(ig, v, s.nodes[v], O);
  return ig;
}

void instantiate_arc(const SchemeArc& e, const OrbitGraph& O, InstantiatedGraph& into) {
  for (uint32_t b = 0; b < O.size(); ++b)
    into.graph.add_link(into.at(e.a, b), into.at(e.b, b), e.dim);
}

InstantiatedGraph instantiate_graph(const GraphScheme& s, const OrbitGraph& O) {
  InstantiatedGraph ig = instantiate_nodes(s, O);
  for (const auto& e : s.arcs) {
    if (e.a >= s.size() || e.b >= s.size()) throw Error(ErrorCode::Schema, "arc end out of range");
    instantiate_arc(e, O, ig);
  }
  return ig;
}

InstantiatedRule instantiate_sides(const RuleScheme& r, const OrbitGraph& O) {
  return InstantiatedRule{instantiate_graph(r.left, O), instantiate_graph(r.right, O)};
}

Rule instantiate_rule(const RuleScheme& r, const OrbitGraph& O) {
  InstantiatedRule ir = instantiate_sides(r, O);
  return Rule(std::move(ir.left.graph), std::move(ir.right.graph), r.dimension, MapKind::GMap,
              r.name);
}

OrbitGraph hook_orbit_graph(const Map& g, const RuleScheme& r, Dart hook_dart) {
  if (r.hooks.empty()) return single_dart_orbit(r.orbit.size());
  const auto hooks = r.hook_nodes();
  const OrbitType& t = r.left.nodes[hooks[0]].label;
  if (t.has_hole())
    throw Error(ErrorCode::Schema, "the reference hook's label " + t.str() + " has `_`",
                "hook " + r.hooks[0]);
  return orbit_graph(g, t, hook_dart);
}

}  // namespace gmr::scheme
