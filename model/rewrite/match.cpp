#include "model/rewrite/match.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <string>
#include <tuple>

#include "model/core/error.hpp"

namespace gmr::rewrite {
using namespace gmr::graph;

namespace {

using Key = std::tuple<Node, Node, int>;

// Number of live arcs src -l-> tgt in g.
size_t count_arcs(const DGraph& g, Node s, Node t, int l) {
  size_t k = 0;
  for (ArcId a : g.out_arcs(s))
    if (g.arc(a).tgt == t && g.arc(a).label == l) ++k;
  return k;
}

// Breadth-first order of L's nodes (components one after the other), with, for each node, an
// already-ordered neighbour and the arc to follow (or none).
struct Step {
  Node v;
  ArcId via = kNoArc;    // arc of L between v and an earlier node
  bool via_out = false;  // true: via = prev -> v (v is the target); false: v -> prev
};

std::vector<Step> bfs_order(const DGraph& L) {
  std::vector<Step> order;
  HandleVector<Node, bool> seen(L.num_nodes(), false);
  for (Node r : L.nodes()) {
    if (seen[r]) continue;
    seen[r] = true;
    std::deque<Node> q{r};
    order.push_back({r, kNoArc, false});
    while (!q.empty()) {
      const Node u = q.front();
      q.pop_front();
      for (ArcId a : L.out_arcs(u)) {
        const Node w = L.arc(a).tgt;
        if (!seen[w]) {
          seen[w] = true;
          order.push_back({w, a, true});
          q.push_back(w);
        }
      }
      for (ArcId a : L.in_arcs(u)) {
        const Node w = L.arc(a).src;
        if (!seen[w]) {
          seen[w] = true;
          order.push_back({w, a, false});
          q.push_back(w);
        }
      }
    }
  }
  return order;
}

// Checks the arcs of L between v (just mapped) and mapped nodes against G (multiplicities).
bool arcs_ok(const DGraph& L, const DGraph& G, const NodeMap& m, Node v) {
  auto check = [&](ArcId a) {
    const Arc& e = L.arc(a);
    if (m[e.src] == kNoNode || m[e.tgt] == kNoNode) return true;
    return count_arcs(L, e.src, e.tgt, e.label) <= count_arcs(G, m[e.src], m[e.tgt], e.label);
  };
  for (ArcId a : L.out_arcs(v))
    if (!check(a)) return false;
  for (ArcId a : L.in_arcs(v))
    if (!check(a)) return false;
  return true;
}

}  // namespace

std::optional<Match> match_from_nodes(const DGraph& L, const DGraph& G, const NodeMap& nodes) {
  if (nodes.size() != L.num_nodes()) return std::nullopt;
  HandleVector<Node, bool> used(G.num_nodes(), false);
  for (Node v : nodes) {
    if (v.index() >= G.num_nodes() || used[v]) return std::nullopt;
    used[v] = true;
  }
  Match m;
  m.node = nodes;
  m.arc.assign(L.num_arc_slots(), kNoArc);
  std::map<Key, size_t> next;  // first-fit over the parallel G arcs
  for (ArcId a : L.arc_slots()) {
    if (!L.arc_alive(a)) continue;
    const Arc& e = L.arc(a);
    const Key k{nodes[e.src], nodes[e.tgt], e.label};
    size_t& skip = next[k];
    size_t seen = 0;
    for (ArcId b : G.out_arcs(nodes[e.src])) {
      if (G.arc(b).tgt != nodes[e.tgt] || G.arc(b).label != e.label) continue;
      if (seen++ == skip) {
        m.arc[a] = b;
        break;
      }
    }
    if (m.arc[a] == kNoArc) return std::nullopt;
    ++skip;
  }
  return m;
}

size_t for_each_match(const DGraph& L, const DGraph& G,
                      const std::function<bool(const Match&)>& f) {
  const auto order = bfs_order(L);
  NodeMap m(L.num_nodes(), kNoNode);
  HandleVector<Node, bool> used(G.num_nodes(), false);
  size_t count = 0;
  bool stop = false;
  std::function<void(size_t)> rec = [&](size_t k) {
    if (stop) return;
    if (k == order.size()) {
      auto mm = match_from_nodes(L, G, m);
      if (mm) {
        ++count;
        if (!f(*mm)) stop = true;
      }
      return;
    }
    const Step& st = order[k];
    std::vector<Node> cand;
    if (st.via == kNoArc) {
      for (Node g : G.nodes()) cand.push_back(g);
    } else {
      const Arc& e = L.arc(st.via);
      cand = st.via_out ? G.successors(m[e.src], e.label) : G.predecessors(m[e.tgt], e.label);
    }
    std::sort(cand.begin(), cand.end());  // parallel arcs give repeated candidates
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    for (Node g : cand) {
      if (used[g]) continue;
      m[st.v] = g;
      used[g] = true;
      if (arcs_ok(L, G, m, st.v)) rec(k + 1);
      used[g] = false;
      m[st.v] = kNoNode;
      if (stop) return;
    }
  };
  rec(0);
  return count;
}

std::vector<Match> find_matches(const DGraph& L, const DGraph& G, size_t limit) {
  std::vector<Match> out;
  if (limit == 0) return out;
  for_each_match(L, G, [&](const Match& m) {
    out.push_back(m);
    return out.size() < limit;
  });
  return out;
}

bool at_most_one_arc_per_label(const DGraph& g, std::string* where) {
  for (Node v : g.nodes()) {
    std::map<int, int> out, in;
    for (ArcId a : g.out_arcs(v)) ++out[g.arc(a).label];
    for (ArcId a : g.in_arcs(v)) ++in[g.arc(a).label];
    for (auto& [l, k] : out)
      if (k > 1) {
        if (where)
          *where = "node " + g.node_str(v) + ": " + std::to_string(k) + " outgoing " +
                   std::to_string(l) + "-arcs";
        return false;
      }
    for (auto& [l, k] : in)
      if (k > 1) {
        if (where)
          *where = "node " + g.node_str(v) + ": " + std::to_string(k) + " incoming " +
                   std::to_string(l) + "-arcs";
        return false;
      }
  }
  return true;
}

std::optional<Match> anchored_match(const DGraph& L, const DGraph& G,
                                    const std::vector<std::pair<Node, Node>>& anchors) {
  std::string where;
  if (!at_most_one_arc_per_label(L, &where))
    throw Error(ErrorCode::Usage,
                "anchored matching needs a combinatorial left-hand side (Def. 35)",
                "left " + where);
  NodeMap m(L.num_nodes(), kNoNode);
  HandleVector<Node, Node> back(G.num_nodes(), kNoNode);
  std::deque<Node> q;
  auto assign = [&](Node l, Node g) -> bool {
    if (m[l] != kNoNode) return m[l] == g;
    if (back[g] != kNoNode) return false;  // injectivity
    m[l] = g;
    back[g] = l;
    q.push_back(l);
    return true;
  };
  for (auto [l, g] : anchors) {
    if (l.index() >= L.num_nodes())
      throw Error(ErrorCode::Usage, "anchor on an unknown node of L",
                  "L node " + std::to_string(l.index()));
    if (g.index() >= G.num_nodes())
      throw Error(ErrorCode::Usage, "anchor on an unknown node of G",
                  "G node " + std::to_string(g.index()));
    if (!assign(l, g)) return std::nullopt;
  }
  auto unique = [&](const std::vector<Node>& c, Node at, int label,
                    const char* dir) -> std::optional<Node> {
    if (c.size() > 1)
      throw Error(ErrorCode::Usage,
                  "anchored matching needs a combinatorial graph: " + std::to_string(c.size()) +
                      " " + dir + " " + std::to_string(label) + "-arcs",
                  "node " + G.node_str(at));
    if (c.empty()) return std::nullopt;
    return c[0];
  };
  while (!q.empty()) {
    const Node u = q.front();
    q.pop_front();
    for (ArcId a : L.out_arcs(u)) {
      auto t = unique(G.successors(m[u], L.arc(a).label), m[u], L.arc(a).label, "outgoing");
      if (!t || !assign(L.arc(a).tgt, *t)) return std::nullopt;
    }
    for (ArcId a : L.in_arcs(u)) {
      auto s = unique(G.predecessors(m[u], L.arc(a).label), m[u], L.arc(a).label, "incoming");
      if (!s || !assign(L.arc(a).src, *s)) return std::nullopt;
    }
  }
  for (Node v : L.nodes())
    if (m[v] == kNoNode)
      throw Error(ErrorCode::Usage,
                  "node not connected to any anchor: give an anchor in each component of L",
                  "L node " + L.node_str(v));
  return match_from_nodes(L, G, m);
}

}  // namespace gmr::rewrite
