#include "checker/smt/cycle_components.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace gmr::smt {
using graph::ArcId;
using graph::DGraph;
using graph::Node;
using rewrite::Rule;

namespace {
bool listed(const std::vector<int>& labels, int l) {
  return std::find(labels.begin(), labels.end(), l) != labels.end();
}
}  // namespace

std::vector<std::vector<std::string>> rule_components(const Rule& r,
                                                      const std::vector<int>& labels) {
  // The rule's nodes by name: L nodes, then the added ones.
  std::vector<std::string> names;
  std::map<std::string, size_t> index;
  auto node = [&](const std::string& name) {
    auto [it, fresh] = index.emplace(name, names.size());
    if (fresh) names.push_back(name);
    return it->second;
  };
  for (Node v : r.left().nodes()) node(r.left().name(v));
  for (Node w : r.right().nodes()) node(r.right().name(w));
  // Union-find over the arcs of the listed labels on both sides.
  std::vector<size_t> parent(names.size());
  std::iota(parent.begin(), parent.end(), size_t{0});
  auto root = [&](size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const DGraph* g : {&r.left(), &r.right()})
    for (ArcId a : g->arc_slots()) {
      if (!g->arc_alive(a) || !listed(labels, g->arc(a).label)) continue;
      const size_t x = root(index.at(g->name(g->arc(a).src)));
      const size_t y = root(index.at(g->name(g->arc(a).tgt)));
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  std::vector<std::vector<std::string>> out;
  std::map<size_t, size_t> component_of_root;
  for (size_t x = 0; x < names.size(); ++x) {
    auto [it, fresh] = component_of_root.emplace(root(x), out.size());
    if (fresh) out.emplace_back();
    out[it->second].push_back(names[x]);
  }
  return out;
}

Rule restrict_rule(const Rule& r, const std::vector<std::string>& nodes,
                   const std::vector<int>& labels) {
  DGraph L, R;
  HandleVector<Node, std::optional<Node>> left(r.left().num_nodes()), right(r.right().num_nodes());
  for (const std::string& name : nodes) {
    if (auto v = r.left().find(name)) left[*v] = L.add_node(name);
    if (auto w = r.right().find(name)) right[*w] = R.add_node(name);
  }
  auto copy_arcs = [&](const DGraph& from, const HandleVector<Node, std::optional<Node>>& to,
                       DGraph& into) {
    for (ArcId a : from.arc_slots()) {
      if (!from.arc_alive(a) || !listed(labels, from.arc(a).label)) continue;
      const auto s = to[from.arc(a).src], t = to[from.arc(a).tgt];
      if (s && t) into.add_arc(*s, *t, from.arc(a).label);
    }
  };
  copy_arcs(r.left(), left, L);
  copy_arcs(r.right(), right, R);
  return Rule(std::move(L), std::move(R), r.dimension(), r.kind(), r.name());
}

std::vector<int> cycle_labels(const MapSpec& spec) {
  std::vector<int> out;
  for (auto [i, j] : spec.cycle_pairs())
    for (int l : {i, j})
      if (!listed(out, l)) out.push_back(l);
  return out;
}

bool cycle_condition_by_components(const Rule& r, CycleReading reading) {
  const std::vector<int> labels = cycle_labels(r.spec());
  for (const auto& k : rule_components(r, labels))
    if (!cycle_condition(restrict_rule(r, k, labels), reading)) return false;
  return true;
}

}  // namespace gmr::smt
