#include "model/rewrite/small_rules.hpp"

#include <string>

#include "model/graph/partial_injections.hpp"

namespace gmr::rewrite {
using graph::DGraph;
using graph::PartialInjection;

void for_each_status_tuple(size_t nodes, const std::function<void(const std::vector<int>&)>& f) {
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

size_t for_each_small_rule(int n, MapKind kind, int max_nodes, const std::vector<int>& labels,
                           const std::function<bool(size_t, const Rule&)>& f) {
  size_t index = 0;
  bool stop = false;
  std::vector<std::vector<PartialInjection>> pinj(static_cast<size_t>(max_nodes) + 1);
  for (size_t m = 0; m <= static_cast<size_t>(max_nodes); ++m)
    pinj[m] = graph::partial_injections(m);
  for (int nodes = 1; nodes <= max_nodes && !stop; ++nodes) {
    for_each_status_tuple(static_cast<size_t>(nodes), [&](const std::vector<int>& st) {
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
        const Rule r(std::move(L), std::move(R), n, kind, "rule" + std::to_string(index));
        if (!f(index++, r)) stop = true;
        size_t li = 0;
        while (li < choice.size() && ++choice[li] == per) choice[li++] = 0;
        if (li == choice.size()) break;
      }
    });
  }
  return index;
}

}  // namespace gmr::rewrite
