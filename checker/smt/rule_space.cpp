#include "checker/smt/rule_space.hpp"

#include <functional>
#include <string>

namespace gmr::smt {
using graph::DGraph;
using graph::Node;

namespace {
using PInj = std::vector<std::pair<Node, Node>>;

std::vector<PInj> partial_injections(size_t m) {
  std::vector<PInj> out;
  PInj cur;
  std::vector<bool> used(m, false);
  std::function<void(size_t)> rec = [&](size_t s) {
    if (s == m) {
      out.push_back(cur);
      return;
    }
    rec(s + 1);
    for (size_t t = 0; t < m; ++t) {
      if (used[t]) continue;
      used[t] = true;
      cur.emplace_back(Node(static_cast<uint32_t>(s)), Node(static_cast<uint32_t>(t)));
      rec(s + 1);
      cur.pop_back();
      used[t] = false;
    }
  };
  rec(0);
  return out;
}

size_t pinj_count(size_t m) {
  // P(m) = P(m-1) + m * ... : computed by enumeration (m is tiny).
  return partial_injections(m).size();
}

// Status tuples (0 preserved, 1 deleted, 2 added) in nondecreasing order.
void status_tuples(size_t nodes, const std::function<void(const std::vector<int>&)>& f) {
  std::vector<int> st(nodes, 0);
  std::function<void(size_t, int)> rec = [&](size_t k, int min) {
    if (k == nodes) return f(st);
    for (int s = min; s < 3; ++s) {
      st[k] = s;
      rec(k + 1, s);
    }
  };
  rec(0, 0);
}
}  // namespace

rewrite::Rule random_rule(std::mt19937_64& rng, int n, MapKind kind, int nodes, const std::vector<int>& labels,
                          const std::string& name) {
  // rng() % k: portable (std::uniform_int_distribution is not specified bit for bit).
  auto below = [&](size_t k) { return static_cast<size_t>(rng() % k); };
  std::vector<int> st(static_cast<size_t>(nodes));
  for (int& s : st) s = static_cast<int>(below(3));
  std::vector<size_t> ln, rn;
  for (size_t x = 0; x < st.size(); ++x) {
    if (st[x] != 2) ln.push_back(x);
    if (st[x] != 1) rn.push_back(x);
  }
  // A random partial injection on m nodes: a random permutation, each pair kept with probability 1/2.
  auto pinj = [&](size_t m) {
    std::vector<Node> perm(m);
    for (size_t k = 0; k < m; ++k) perm[k] = Node(static_cast<uint32_t>(k));
    for (size_t k = m; k > 1; --k) std::swap(perm[k - 1], perm[below(k)]);
    PInj out;
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
        s += " " + g.name(g.arc(a).src) + "-" + std::to_string(g.arc(a).label) + "->" + g.name(g.arc(a).tgt);
    s += "}";
  }
  return s;
}

size_t count_rules(int nodes, size_t labels) {
  size_t total = 0;
  status_tuples(static_cast<size_t>(nodes), [&](const std::vector<int>& st) {
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
  size_t index = 0;
  bool stop = false;
  std::vector<std::vector<PInj>> pinj(static_cast<size_t>(max_nodes) + 1);
  for (size_t m = 0; m <= static_cast<size_t>(max_nodes); ++m) pinj[m] = partial_injections(m);
  for (int nodes = 1; nodes <= max_nodes && !stop; ++nodes) {
    status_tuples(static_cast<size_t>(nodes), [&](const std::vector<int>& st) {
      if (stop) return;
      std::vector<size_t> ln, rn;
      for (size_t x = 0; x < st.size(); ++x) {
        if (st[x] != 2) ln.push_back(x);
        if (st[x] != 1) rn.push_back(x);
      }
      const auto& pl = pinj[ln.size()];
      const auto& pr = pinj[rn.size()];
      const size_t per = pl.size() * pr.size();
      std::vector<size_t> choice(labels.size(), 0);
      while (!stop) {
        DGraph L, R;
        for (size_t x : ln) L.add_node(std::string(1, static_cast<char>('a' + x)));
        for (size_t x : rn) R.add_node(std::string(1, static_cast<char>('a' + x)));
        for (size_t li = 0; li < labels.size(); ++li) {
          for (auto [s, t] : pl[choice[li] / pr.size()]) L.add_arc(s, t, labels[li]);
          for (auto [s, t] : pr[choice[li] % pr.size()]) R.add_arc(s, t, labels[li]);
        }
        const rewrite::Rule r(std::move(L), std::move(R), n, kind, "rule" + std::to_string(index));
        if (!f(index++, r)) stop = true;
        size_t li = 0;
        while (li < choice.size() && ++choice[li] == per) choice[li++] = 0;
        if (li == choice.size()) break;
      }
    });
  }
  return index;
}

}  // namespace gmr::smt
