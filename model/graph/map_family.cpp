#include "model/graph/map_family.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/graph/dart_permutations.hpp"

namespace gmr::graph {

std::vector<Map> connected_maps(int n, MapKind kind, size_t k) {
  if (k == 0) return {};
  const MapSpec spec{n, kind};
  const int lo = spec.lowest_dim();
  if (n < lo || n >= kMaxDim)
    throw Error(ErrorCode::Range, "dimension out of range", "n=" + std::to_string(n));
  const auto inv = involutions(k);
  const auto perm = kind == MapKind::OMap ? permutations(k) : std::vector<DartPermutation>{};
  std::vector<const DartPermutation*> chosen(static_cast<size_t>(n + 1), nullptr);
  std::set<Word> seen;
  std::vector<Map> out;
  std::function<void(int)> rec = [&](int d) {
    if (d > n) {
      std::vector<const DartPermutation*> s(chosen.begin() + lo, chosen.end());
      if (!connected(s, k)) return;
      Map g(n, kind);
      g.add_darts(k);
      for (int i = lo; i <= n; ++i)
        for (Dart x = 0; x < k; ++x) g.set_alpha(i, x, (*chosen[static_cast<size_t>(i)])[x]);
      if (seen.insert(component_signature(g, 0)).second) out.push_back(std::move(g));
      return;
    }
    const auto& pool = spec.is_involutive_dim(d) ? inv : perm;
    for (const DartPermutation& p : pool) {
      bool ok = true;
      for (auto [i, j] : spec.cycle_pairs())
        if (j == d && ok) ok = commute(*chosen[static_cast<size_t>(i)], p);
      if (!ok) continue;
      chosen[static_cast<size_t>(d)] = &p;
      rec(d + 1);
    }
  };
  rec(lo);
  return out;
}

MapFamily map_family(int n, MapKind kind, size_t max_darts) {
  MapFamily f;
  f.n = n;
  f.kind = kind;
  f.max_darts = max_darts;
  std::vector<std::vector<Map>> conn(max_darts + 1);
  for (size_t s = 1; s <= max_darts; ++s) conn[s] = connected_maps(n, kind, s);
  // Multisets of components, in nondecreasing (size, index) order.
  std::vector<std::pair<size_t, size_t>> pick;
  std::vector<std::pair<size_t, Map>> all;
  std::function<void(size_t, size_t, size_t)> rec = [&](size_t total, size_t s0, size_t i0) {
    if (!pick.empty()) {
      Map g(n, kind);
      for (auto [s, idx] : pick) {
        const Map& c = conn[s][idx];
        const Dart base = g.add_darts(s);
        for (int i = g.lowest_dim(); i <= n; ++i)
          for (Dart x = 0; x < s; ++x) g.set_alpha(i, base + x, base + c.alpha(i, x));
      }
      all.emplace_back(total, std::move(g));
    }
    for (size_t s = s0; s + total <= max_darts; ++s)
      for (size_t idx = (s == s0 ? i0 : 0); idx < conn[s].size(); ++idx) {
        pick.emplace_back(s, idx);
        rec(total + s, s, idx);
        pick.pop_back();
      }
  };
  rec(0, 1, 0);
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [s, g] : all) {
    f.graphs.push_back(to_dgraph(g));
    f.maps.push_back(std::move(g));
  }
  return f;
}

}  // namespace gmr::graph
