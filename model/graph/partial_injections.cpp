#include "model/graph/partial_injections.hpp"

#include <functional>

namespace gmr::graph {

std::vector<PartialInjection> partial_injections(size_t m) {
  std::vector<PartialInjection> out;
  PartialInjection cur;
  std::vector<bool> used_t(m, false);
  std::function<void(size_t)> rec = [&](size_t s) {
    if (s == m) {
      out.push_back(cur);
      return;
    }
    rec(s + 1);  // s has no arc
    for (size_t t = 0; t < m; ++t) {
      if (used_t[t]) continue;
      used_t[t] = true;
      cur.emplace_back(Node(static_cast<uint32_t>(s)), Node(static_cast<uint32_t>(t)));
      rec(s + 1);
      cur.pop_back();
      used_t[t] = false;
    }
  };
  rec(0);
  return out;
}

}  // namespace gmr::graph
