#include "checker/smt/rule_space.hpp"

#include <functional>
#include <string>

#include "model/graph/partial_injections.hpp"
#include "model/rewrite/small_rules.hpp"

namespace gmr::smt {
using graph::DGraph;
using graph::Node;
using graph::partial_injections;
using graph::PartialInjection;

namespace {
size_t pinj_count(size_t m) {
  // P(m) = P(m-1) + m * ... : computed by enumeration (m is tiny).
  return partial_injections(m).size();
}
}  // namespace

rewrite::Rule random_rule(std::mt19937_64& rng, int n, MapKind kind, int nodes,
                          const std::vector<int>& labels, const std::string& name) {
  // rng() % k: portable (std::uniform_int_distribution is not specified bit for bit).
  auto below = [&](size_t k) { return static_cast<size_t>(rng() % k); };
  std::vector<int> st(static_cast<size_t>(nodes));
  for (int& s : st) s = static_cast<int>(below(3));
  std::vector<size_t> ln, rn;
  for (size_t x = 0; x < st.size(); ++x) {
    if (st[x] != 2) ln.push_back(x);
    if (st[x] != 1) rn.push_back(x);
  }
  // A random partial injection on m nodes: a random permutation, each pair kept with probability
  // 1/2.
  auto pinj = [&](size_t m) {
    std::vector<Node> perm(m);
    for (size_t k = 0; k < m; ++k) perm[k] = Node(static_cast<uint32_t>(k));
    for (size_t k = m; k > 1; --k) std::swap(perm[k - 1], perm[below(k)]);
    PartialInjection out;
    for (size_t k = 0; k < m; ++k)
      if (below(2)) out.emplace_back(Node(static_cast<uint32_t>(k)), perm[k]);
    return out;
  };
  DGraph L, R;
  for (size_t x : ln) L.add_node(std::string(1, static_cast<char>('a' + x)));
  for (size_t x : rn) R.add_node(std::string(1, static_cast<char>('a' + x)));
  for (int i : labels) {
    for (auto [s, t] : pinj(ln.size())) L.add_arc(s, t, i);
    for (auto [s, t] : pinj(rn.size())) R.add_arc(s, t, i);
  }
  return rewrite::Rule(std::move(L), std::move(R), n, kind, name);
}

std::string rule_text(const rewrite::Rule& r) {
  std::string s;
  for (graph::Side side : graph::kSides) {
    const DGraph& g = r.side(side);
    s += side == graph::Side::R ? " => R {" : "L {";
    for (Node v : g.nodes()) s += (v != Node(0) ? " " : "") + g.name(v);
    s += ";";
    for (graph::ArcId a : g.arc_slots())
      if (g.arc_alive(a))
        s += " " + g.name(g.arc(a).src) + "-" + std::to_string(g.arc(a).label) + "->" +
             g.name(g.arc(a).tgt);
    s += "}";
  }
  return s;
}

size_t count_rules(int nodes, size_t labels) {
  size_t total = 0;
  rewrite::for_each_status_tuple(static_cast<size_t>(nodes), [&](const std::vector<int>& st) {
    size_t l = 0, r = 0;
    for (int s : st) {
      l += s != 2;
      r += s != 1;
    }
    size_t per = pinj_count(l) * pinj_count(r), all = 1;
    for (size_t k = 0; k < labels; ++k) all *= per;
    total += all;
  });
  return total;
}

size_t for_each_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& labels,
                     const std::function<bool(size_t, const rewrite::Rule&)>& f) {
  return rewrite::for_each_small_rule(n, kind, max_nodes, labels, f);
}

}  // namespace gmr::smt
