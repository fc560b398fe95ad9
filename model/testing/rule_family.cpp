#include "model/testing/rule_family.hpp"

#include <algorithm>
#include <functional>
#include <string>

#include "model/core/error.hpp"
#include "model/rewrite/match.hpp"
#include "model/rewrite/small_rules.hpp"
#include "model/testing/random_maps.hpp"

namespace gmr::testing {
using namespace gmr::graph;
using namespace gmr::rewrite;

size_t for_each_small_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& arc_labels,
                           const std::function<bool(const Rule&)>& f) {
  return rewrite::for_each_small_rule(n, kind, max_nodes, arc_labels,
                                      [&](size_t, const Rule& r) { return f(r); });
}

Rule random_rule_from_maps(std::mt19937_64& rng, const MapFamily& fam, size_t max_left_nodes) {
  if (fam.maps.empty()) throw Error(ErrorCode::Usage, "empty map family", "random_rule_from_maps");
  auto pick = [&](size_t k) { return std::uniform_int_distribution<size_t>(0, k - 1)(rng); };
  auto coin = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; };
  const DGraph& G = fam.graphs[pick(fam.graphs.size())];
  std::vector<Node> nodes(G.nodes().begin(), G.nodes().end());
  std::shuffle(nodes.begin(), nodes.end(), rng);
  nodes.resize(1 + pick(std::min(max_left_nodes, nodes.size())));
  const std::string lnames = "abcdefgh", anames = "uvwxyz";
  HandleVector<Node, Node> lpos(G.num_nodes(), kNoNode);
  DGraph L;
  for (size_t k = 0; k < nodes.size(); ++k) lpos[nodes[k]] = L.add_node(std::string(1, lnames[k]));
  const double drop = coin(0.5) ? 0.0 : 0.15;
  for (ArcId a : G.arc_slots()) {
    const Arc& e = G.arc(a);
    if (lpos[e.src] != kNoNode && lpos[e.tgt] != kNoNode && !coin(drop))
      L.add_arc(lpos[e.src], lpos[e.tgt], e.label);
  }
  std::vector<bool> deleted(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) deleted[k] = coin(0.25);
  std::vector<size_t> kept;
  for (size_t k = 0; k < nodes.size(); ++k)
    if (!deleted[k]) kept.push_back(k);
  const size_t added = pick(3);
  // R: around the preserved nodes, an induced subgraph of another map big enough.
  std::vector<size_t> big;
  for (size_t m = 0; m < fam.graphs.size(); ++m)
    if (fam.graphs[m].num_nodes() >= kept.size() + added) big.push_back(m);
  DGraph R;
  if (big.empty() || coin(0.2)) {
    // Fallback: R = the preserved part of L with a few toggled arcs, plus added nodes with loops.
    HandleVector<Node, Node> rpos(L.num_nodes(), kNoNode);
    for (size_t k : kept)
      rpos[Node(static_cast<uint32_t>(k))] = R.add_node(L.name(Node(static_cast<uint32_t>(k))));
    for (ArcId a : L.arc_slots()) {
      const Arc& e = L.arc(a);
      if (rpos[e.src] != kNoNode && rpos[e.tgt] != kNoNode && !coin(0.2))
        R.add_arc(rpos[e.src], rpos[e.tgt], e.label);
    }
    for (size_t k = 0; k < added; ++k) {
      const Node v = R.add_node(std::string(1, anames[k]));
      for (int i : MapSpec{fam.n, fam.kind}.labels())
        if (!coin(0.1)) R.add_arc(v, v, i);
    }
  } else {
    const DGraph& G2 = fam.graphs[big[pick(big.size())]];
    std::vector<Node> pool(G2.nodes().begin(), G2.nodes().end());
    std::shuffle(pool.begin(), pool.end(), rng);
    HandleVector<Node, Node> rpos(G2.num_nodes(), kNoNode);
    size_t next = 0;
    for (size_t k : kept) rpos[pool[next++]] = R.add_node(L.name(Node(static_cast<uint32_t>(k))));
    for (size_t k = 0; k < added; ++k) rpos[pool[next++]] = R.add_node(std::string(1, anames[k]));
    for (ArcId a : G2.arc_slots()) {
      const Arc& e = G2.arc(a);
      if (rpos[e.src] != kNoNode && rpos[e.tgt] != kNoNode && !coin(drop))
        R.add_arc(rpos[e.src], rpos[e.tgt], e.label);
    }
  }
  // Remove deleted nodes' names from R side: build L with all nodes (deleted ones stay in L only).
  return Rule(std::move(L), std::move(R), fam.n, fam.kind, "random");
}

Rule random_small_rule(std::mt19937_64& rng, int n, MapKind kind, int max_nodes) {
  if (max_nodes < 1 || max_nodes > 8)
    throw Error(ErrorCode::Range, "random_small_rule: 1..8 nodes");
  const size_t count = static_cast<size_t>(uniform(rng, 1, static_cast<uint64_t>(max_nodes)));
  const std::string names = "abcdefgh";
  DGraph L, R;
  std::vector<Node> lpos(count, kNoNode), rpos(count, kNoNode);
  for (size_t x = 0; x < count; ++x) {
    const uint64_t status = uniform(rng, 0, 2);  // 0 preserved, 1 deleted, 2 added
    if (status != 2) lpos[x] = L.add_node(std::string(1, names[x]));
    if (status != 1) rpos[x] = R.add_node(std::string(1, names[x]));
  }
  // A random partial injection on the nodes of one side, as i-arcs.
  auto arcs = [&](DGraph& side, int i) {
    const size_t m = side.num_nodes();
    HandleVector<Node, bool> used(m, false);
    for (Node s : side.nodes()) {
      if (chance(rng, 30)) continue;
      const Node t(static_cast<uint32_t>(uniform(rng, 0, m - 1)));
      if (used[t]) continue;
      used[t] = true;
      side.add_arc(s, t, i);
    }
  };
  for (int i : MapSpec{n, kind}.labels()) {
    if (L.num_nodes()) arcs(L, i);
    if (R.num_nodes()) arcs(R, i);
  }
  return Rule(std::move(L), std::move(R), n, kind, "random-small");
}

Rule component_replacement_rule(std::mt19937_64& rng, const MapFamily& fam) {
  if (fam.graphs.empty())
    throw Error(ErrorCode::Usage, "empty map family", "component_replacement_rule");
  const DGraph& GL = fam.graphs[uniform(rng, 0, fam.graphs.size() - 1)];
  const DGraph& GR = fam.graphs[uniform(rng, 0, fam.graphs.size() - 1)];
  const size_t p = uniform(rng, 0, std::min(GL.num_nodes(), GR.num_nodes()));
  auto copy = [](const DGraph& G, const std::function<std::string(Node)>& name) {
    DGraph out;
    for (Node v : G.nodes()) out.add_node(name(v));
    for (ArcId a : G.arc_slots())
      if (G.arc_alive(a)) out.add_arc(G.arc(a).src, G.arc(a).tgt, G.arc(a).label);
    return out;
  };
  DGraph L = copy(GL, [](Node v) { return "l" + std::to_string(v.index()); });
  DGraph R =
      copy(GR, [p](Node v) { return (v.index() < p ? "l" : "r") + std::to_string(v.index()); });
  return Rule(std::move(L), std::move(R), fam.n, fam.kind, "component-replacement");
}

}  // namespace gmr::testing
