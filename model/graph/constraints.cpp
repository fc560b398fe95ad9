#include "model/graph/constraints.hpp"

#include <functional>

namespace gmr::graph {

namespace {

// A ConstraintViolation names nodes by their index (constraint_violation.hpp).
std::vector<uint32_t> indices(const std::vector<Node>& nodes) {
  std::vector<uint32_t> out;
  out.reserve(nodes.size());
  for (Node x : nodes) out.push_back(x.index());
  return out;
}

}  // namespace

std::string to_text(const ConstraintViolation& v, const DGraph& g) {
  std::string s = std::string(to_text(v.constraint)) + " " +
                  condition_text(symbol(v.constraint), v.i, v.j) + " at node " +
                  g.node_str(Node(v.at)) + ": " + v.message;
  if (!v.path.empty()) {
    s += " [path";
    for (uint32_t x : v.path) s += " " + g.node_str(Node(x));
    s += "]";
  }
  return s;
}

std::vector<ConstraintViolation> check_incident_arcs(const DGraph& g, Node v, int i) {
  std::vector<ConstraintViolation> out;
  const auto succ = g.successors(v, i), pred = g.predecessors(v, i);
  const std::string li = std::to_string(i);
  auto add = [&](std::string message, std::vector<Node> path) {
    out.push_back({.constraint = Constraint::IncidentArcs,
                   .at = v.index(),
                   .i = i,
                   .path = indices(path),
                   .message = std::move(message)});
  };
  if (succ.empty()) add("no outgoing " + li + "-arc", {});
  if (succ.size() > 1) {
    std::vector<Node> path{v};
    path.insert(path.end(), succ.begin(), succ.end());
    add(std::to_string(succ.size()) + " outgoing " + li + "-arcs", std::move(path));
  }
  if (pred.empty()) add("no incoming " + li + "-arc", {});
  if (pred.size() > 1) {
    std::vector<Node> path = pred;
    path.push_back(v);
    add(std::to_string(pred.size()) + " incoming " + li + "-arcs", std::move(path));
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
  // The i-arc a -> b has no reverse.
  auto add = [&](Node a, Node b) {
    out.push_back({.constraint = Constraint::NonOrientation,
                   .at = v.index(),
                   .i = i,
                   .path = {a.index(), b.index()},
                   .message = "the " + std::to_string(i) + "-arc " + g.node_str(a) + "->" +
                              g.node_str(b) + " has no reverse"});
  };
  for (Node w : g.successors(v, i))
    if (!has_arc(w, v)) add(v, w);
  for (Node w : g.predecessors(v, i))
    if (!has_arc(v, w)) add(w, v);
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
                                         : "the " + l + l + "-path stops after " +
                                               std::to_string(longest.size() - 1) + " arcs";
  return {{.constraint = Constraint::Cycle,
           .at = v.index(),
           .i = i,
           .j = j,
           .path = indices(longest),
           .message = std::move(what)}};
}

std::vector<ConstraintViolation> check_map_constraints(const DGraph& g, int n, MapKind kind) {
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
      out.push_back({.constraint = Constraint::IncidentArcs,
                     .at = e.src.index(),
                     .i = e.label,
                     .path = {e.src.index(), e.tgt.index()},
                     .message = "label " + std::to_string(e.label) + " outside " +
                                std::to_string(lo) + ".." + std::to_string(n)});
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
