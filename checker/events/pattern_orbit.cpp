#include "checker/events/pattern_orbit.hpp"

#include <numeric>

namespace gmr::events {

bool has_link(const scheme::GraphScheme& side, uint32_t m, int i) {
  for (int d : side.nodes[m].label.dims())
    if (d == i) return true;
  return side.count_explicit(m, i) > 0;
}

namespace {
uint32_t find(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}
}  // namespace

PatternOrbits pattern_orbits(const scheme::GraphScheme& side, Side which, DimMask o) {
  PatternOrbits p;
  p.side = which;
  p.orbit = o;
  const uint32_t n = static_cast<uint32_t>(side.size());
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& e : side.arcs)
    if (e.dim >= 0 && (o >> e.dim & 1u)) parent[find(parent, e.a)] = find(parent, e.b);
  p.class_of.assign(n, 0);
  std::vector<uint32_t> index(n, UINT32_MAX);
  for (uint32_t m = 0; m < n; ++m) {
    const uint32_t r = find(parent, m);
    if (index[r] == UINT32_MAX) {
      index[r] = static_cast<uint32_t>(p.nodes.size());
      p.nodes.emplace_back();
    }
    p.class_of[m] = index[r];
    p.nodes[index[r]].push_back(m);
  }
  p.complete.assign(p.nodes.size(), true);
  p.positions.assign(p.nodes.size(), {});
  for (size_t c = 0; c < p.nodes.size(); ++c) {
    std::vector<bool> pos;
    for (uint32_t m : p.nodes[c]) {
      const auto& label = side.nodes[m].label.dims();
      if (pos.size() < label.size()) pos.resize(label.size(), false);
      for (size_t k = 0; k < label.size(); ++k)
        if (label[k] >= 0 && (o >> label[k] & 1u)) pos[k] = true;
      for (int i = 0; i < kMaxDim; ++i)
        if ((o >> i & 1u) && !has_link(side, m, i)) p.complete[c] = false;
    }
    for (uint32_t k = 0; k < pos.size(); ++k)
      if (pos[k]) p.positions[c].push_back(k);
  }
  return p;
}

}  // namespace gmr::events
