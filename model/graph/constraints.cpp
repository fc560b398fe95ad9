#include "model/graph/constraints.hpp"

#include <functional>

namespace gmr::graph {

const char* to_string(ConstraintKind k) {
  switch (k) {
    case ConstraintKind::IncidentArcs: return "incident-arcs";
    case ConstraintKind::NonOrientation: return "non-orientation";
    case ConstraintKind::Cycle: return "cycle";
  }
  return "?";
}

std::string ConstraintViolation::describe(const DGraph& g) const {
  std::string s = std::string(to_string(kind)) + " ";
  s += kind == ConstraintKind::Cycle ? "C(" + std::to_string(i) + "," + std::to_string(j) + ")"
                                     : (kind == ConstraintKind::IncidentArcs ? "I(" : "O(") + std::to_string(i) + ")";
  s += " at node " + g.node_str(node) + ": " + what;
  if (!path.empty()) {
    s += " [path";
    for (Node v : path) s += " " + g.node_str(v);
    s += "]";
  }
  return s;
}

std::vector<ConstraintViolation> check_incident_arcs(const DGraph& g, Node v, int i) {
  std::vector<ConstraintViolation> out;
  const auto succ = g.successors(v, i), pred = g.predecessors(v, i);
  const std::string li = std::to_string(i);
  if (succ.empty()) out.push_back({ConstraintKind::IncidentArcs, v, i, -1, "no outgoing " + li + "-arc", {}});
  if (succ.size() > 1) {
    ConstraintViolation c{ConstraintKind::IncidentArcs, v, i, -1, std::to_string(succ.size()) + " outgoing " + li + "-arcs", {}};
    c.path = {v};
    c.path.insert(c.path.end(), succ.begin(), succ.end());
    out.push_back(std::move(c));
  }
  if (pred.empty()) out.push_back({ConstraintKind::IncidentArcs, v, i, -1, "no incoming " + li + "-arc", {}});
  if (pred.size() > 1) {
    ConstraintViolation c{ConstraintKind::IncidentArcs, v, i, -1, std::to_string(pred.size()) + " incoming " + li + "-arcs", {}};
    c.path = pred;
    c.path.push_back(v);
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<ConstraintViolation> check_non_orientation(const DGraph& g, Node v, int i) {
  std::vector<ConstraintViolation> out;
  auto has_arc = [&](Node a, Node b) {
    for (ArcId e : g.out_arcs(a))
      if (g.arc(e).label == i && g.arc(e).tgt == b) return true;
    return false;
  };
  for (Node w : g.successors(v, i))
    if (!has_arc(w, v))
      out.push_back({ConstraintKind::NonOrientation, v, i, -1,
                     "the " + std::to_string(i) + "-arc " + g.node_str(v) + "->" + g.node_str(w) + " has no reverse", {v, w}});
  for (Node w : g.predecessors(v, i))
    if (!has_arc(v, w))
      out.push_back({ConstraintKind::NonOrientation, v, i, -1,
                     "the " + std::to_string(i) + "-arc " + g.node_str(w) + "->" + g.node_str(v) + " has no reverse", {w, v}});
  return out;
}

std::vector<ConstraintViolation> check_cycle(const DGraph& g, Node v, int i, int j) {
  // Existential: search the ijij-paths from v (bounded by out-degrees) for one back to v.
  const int word[4] = {i, j, i, j};
  std::vector<Node> path{v}, longest{v};
  std::function<bool(Node, int)> dfs = [&](Node u, int k) -> bool {
    if (k == 4) return u == v;
    for (Node w : g.successors(u, word[k])) {
      path.push_back(w);
      if (path.size() > longest.size() || (k == 3 && longest.size() < 5)) longest = path;
      if (dfs(w, k + 1)) return true;
      path.pop_back();
    }
    return false;
  };
  if (dfs(v, 0)) return {};
  std::string l = std::to_string(i) + std::to_string(j);
  std::string what = longest.size() == 5 ? "no " + l + l + "-path from this node returns to it"
                                         : "the " + l + l + "-path stops after " + std::to_string(longest.size() - 1) + " arcs";
  return {{ConstraintKind::Cycle, v, i, j, what, longest}};
}

std::vector<ConstraintViolation> check_gmap_constraints(const DGraph& g, int n, MapKind kind) {
  std::vector<ConstraintViolation> out;
  const MapSpec spec{n, kind};
  const int lo = spec.lowest_dim();
  auto append = [&](std::vector<ConstraintViolation> v) {
    for (auto& c : v) out.push_back(std::move(c));
  };
  for (ArcId a : g.arc_slots()) {
    if (!g.arc_alive(a)) continue;
    const Arc& e = g.arc(a);
    if (e.label < lo || e.label > n)
      out.push_back({ConstraintKind::IncidentArcs, e.src, e.label, -1,
                     "label " + std::to_string(e.label) + " outside " + std::to_string(lo) + ".." + std::to_string(n),
                     {e.src, e.tgt}});
  }
  for (Node v : g.nodes()) {
    for (int i : spec.labels()) append(check_incident_arcs(g, v, i));
    for (int i : spec.labels())
      if (spec.is_involutive_dim(i)) append(check_non_orientation(g, v, i));
    for (auto [i, j] : spec.cycle_pairs()) append(check_cycle(g, v, i, j));
  }
  return out;
}

}  // namespace gmr::graph
