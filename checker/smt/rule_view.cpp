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
    case ElemStatus::Preserved: return condition::Status::Preserved;
    case ElemStatus::Deleted: return condition::Status::Deleted;
    default: return condition::Status::Added;
  }
}

condition::Graph side(const rewrite::Rule& r, Side which) {
  const DGraph& g = r.side(which);
  condition::Graph out;
  std::vector<unsigned> index(g.num_nodes());
  for (Node v = 0; v < g.num_nodes(); ++v) {
    condition::Node n{g.name(v), status(r.node_status(which, v)), std::nullopt};
    if (auto o = which == Side::R ? r.left_of(v) : r.right_of(v)) n.other = *o;
    out.nodes.push_back(std::move(n));
  }
  for (ArcId a = 0; a < g.num_arc_slots(); ++a)
    if (g.arc_alive(a))
      out.arcs.push_back({g.arc(a).src, g.arc(a).tgt, g.arc(a).label, status(r.arc_status(which, a))});
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

}  // namespace gmr::smt
