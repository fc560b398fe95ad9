#include "checker/smt/rule_view.hpp"

namespace gmr::smt {
using graph::ArcId;
using graph::DGraph;
using graph::ElemStatus;
using graph::Node;
using graph::Side;

namespace {
condition::Status status(ElemStatus s) {
  switch (s) {
    case ElemStatus::Preserved:
      return condition::Status::Preserved;
    case ElemStatus::Deleted:
      return condition::Status::Deleted;
    default:
      return condition::Status::Added;
  }
}

condition::Graph side(const rewrite::Rule& r, Side which) {
  const DGraph& g = r.side(which);
  condition::Graph out;
  std::vector<unsigned> index(g.num_nodes());
  for (Node v : g.nodes()) {
    condition::Node n{g.name(v), status(r.node_status(which, v)), std::nullopt};
    if (auto o = which == Side::R ? r.left_of(v) : r.right_of(v)) n.other = o->index();
    out.nodes.push_back(std::move(n));
  }
  for (ArcId a : g.arc_slots())
    if (g.arc_alive(a))
      out.arcs.push_back({g.arc(a).src.index(), g.arc(a).tgt.index(), g.arc(a).label,
                          status(r.arc_status(which, a))});
  return out;
}
}  // namespace

condition::RuleView to_view(const rewrite::Rule& r) {
  condition::RuleView v;
  v.name = r.name();
  v.model = r.kind() == MapKind::OMap ? condition::Model::OMap : condition::Model::GMap;
  v.n = r.dimension();
  v.left = side(r, Side::L);
  v.right = side(r, Side::R);
  return v;
}

condition::SchemeView to_view(const scheme::RuleScheme& s) {
  condition::SchemeView v;
  v.name = s.name;
  v.n = s.dimension;
  for (size_t p = 0; p < s.orbit.size(); ++p) v.orbit.push_back(s.orbit[p]);
  for (bool right : {false, true}) {
    const scheme::GraphScheme& g = right ? s.right : s.left;
    condition::SchemeGraph& out = right ? v.right : v.left;
    for (uint32_t n = 0; n < g.size(); ++n) {
      condition::SchemeNode node;
      node.name = g.nodes[n].name;
      for (size_t p = 0; p < g.nodes[n].label.size(); ++p)
        node.label.push_back(g.nodes[n].label[p] == OrbitType::kHole ? -1 : g.nodes[n].label[p]);
      node.status = status(right ? s.role_right(n) : s.role_left(n));
      out.nodes.push_back(std::move(node));
    }
    for (const auto& a : g.arcs) out.arcs.push_back({a.a, a.b, a.dim});
  }
  v.hooks = s.hooks;
  return v;
}

}  // namespace gmr::smt
