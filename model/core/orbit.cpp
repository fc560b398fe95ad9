#include "model/core/orbit.hpp"

#include <unordered_map>

#include "model/core/error.hpp"

namespace gmr {

void require_orbit_type(const Map& g, const OrbitType& o) {
  for (int i : o.dims()) {
    if (i == OrbitType::kHole)
      throw Error(ErrorCode::Usage,
                  "orbit type " + o.str() + " has '_' where a set of dimensions is expected");
    if (!g.has_dim(i))
      throw Error(ErrorCode::Range, "dimension " + std::to_string(i) + " of orbit type " + o.str() +
                                        " is not a dimension of this " +
                                        std::to_string(g.dimension()) + "-" +
                                        (g.is_omap() ? "O-map" : "G-map"));
  }
}

static void require_dart(const Map& g, Dart d) {
  if (!g.alive(d)) throw Error(ErrorCode::Range, "no such dart", "dart " + std::to_string(d));
}

std::vector<Dart> orbit(const Map& g, const OrbitType& o, Dart d) {
  require_orbit_type(g, o);
  require_dart(g, d);
  ScopedMarker seen(g);
  std::vector<Dart> out{d};
  seen.mark(d);
  for (size_t head = 0; head < out.size(); ++head) {  // BFS queue = out itself
    const Dart v = out[head];
    for (int i : o.dims()) {
      const Dart w = g.alpha(i, v);
      if (!seen.test(w)) {
        seen.mark(w);
        out.push_back(w);
      }
    }
  }
  for (Dart v : out) seen.unmark(v);
  seen.set_clean();
  return out;
}

template <class F>
static size_t for_each_orbit(const Map& g, DimMask mask, F&& on_representative) {
  return visit_all_orbits(g, mask, on_representative, [](Dart) {});
}

size_t count_orbits(const Map& g, const OrbitType& o) {
  require_orbit_type(g, o);
  return for_each_orbit(g, o.mask(), [](Dart) {});
}

std::vector<Dart> orbit_representatives(const Map& g, const OrbitType& o) {
  require_orbit_type(g, o);
  std::vector<Dart> reps;
  for_each_orbit(g, o.mask(), [&](Dart d) { reps.push_back(d); });
  return reps;
}

OrbitType cell_type(const Map& g, int i) {
  if (i < 0 || i > g.dimension())
    throw Error(ErrorCode::Range, "cell dimension " + std::to_string(i) + " outside 0.." +
                                      std::to_string(g.dimension()));
  if (g.is_omap() && i == 0)
    throw Error(ErrorCode::Usage,
                "O-map vertices are not an orbit of a set of dimensions; use omap_vertex");
  std::vector<int> dims;
  for (int d = g.lowest_dim(); d <= g.dimension(); ++d)
    if (d != i) dims.push_back(d);
  return OrbitType(std::move(dims));
}

// O-map vertex traversal: neighbours of v are beta_k(beta_1(v)) for k = 2..n. Each such
// composition is a permutation, so forward reachability gives the orbit.
template <class F>
static size_t visit_omap_vertex_marked(const Map& g, Dart d, int m, std::vector<Dart>& stack,
                                       F&& f) {
  size_t count = 0;
  stack.clear();
  stack.push_back(d);
  g.mark(d, m);
  while (!stack.empty()) {
    const Dart v = stack.back();
    stack.pop_back();
    f(v);
    ++count;
    const Dart b1 = g.alpha(1, v);
    for (int k = 2; k <= g.dimension(); ++k) {
      const Dart w = g.alpha(k, b1);
      if (!g.is_marked(w, m)) {
        g.mark(w, m);
        stack.push_back(w);
      }
    }
  }
  return count;
}

std::vector<Dart> omap_vertex(const Map& g, Dart d) {
  require_dart(g, d);
  if (!g.is_omap()) return orbit(g, cell_type(g, 0), d);
  ScopedMarker seen(g);
  std::vector<Dart> stack, out;
  visit_omap_vertex_marked(g, d, seen.id(), stack, [&](Dart v) { out.push_back(v); });
  for (Dart v : out) seen.unmark(v);
  seen.set_clean();
  return out;
}

size_t count_cells(const Map& g, int i) {
  if (g.is_omap() && i == 0) {
    ScopedMarker seen(g);
    std::vector<Dart> stack;
    size_t n = 0;
    g.for_each_dart([&](Dart d) {
      if (seen.test(d)) return;
      ++n;
      visit_omap_vertex_marked(g, d, seen.id(), stack, [](Dart) {});
    });
    return n;
  }
  return for_each_orbit(g, cell_type(g, i).mask(), [](Dart) {});
}

std::vector<size_t> count_all_cells(const Map& g) {
  std::vector<size_t> c;
  for (int i = 0; i <= g.dimension(); ++i) c.push_back(count_cells(g, i));
  return c;
}

long long euler_characteristic(const Map& g) {
  long long chi = 0;
  const auto c = count_all_cells(g);
  for (size_t i = 0; i < c.size(); ++i) chi += (i % 2 == 0 ? 1 : -1) * static_cast<long long>(c[i]);
  return chi;
}

size_t count_components(const Map& g) {
  return for_each_orbit(g, g.dims_mask(), [](Dart) {});
}

std::vector<Dart> free_darts(const Map& g, int i) {
  if (!g.has_dim(i))
    throw Error(ErrorCode::Range, "dimension " + std::to_string(i) + " not in map");
  std::vector<Dart> out;
  g.for_each_dart([&](Dart d) {
    if (g.is_free(i, d)) out.push_back(d);
  });
  return out;
}

bool is_closed(const Map& g) {
  const int n = g.dimension();
  bool closed = true;
  g.for_each_dart([&](Dart d) {
    if (g.is_free(n, d)) closed = false;
  });
  return closed;
}

size_t count_boundary_cells(const Map& g) {
  const int n = g.dimension();
  if (n < 1 || g.is_omap()) return 0;
  DimMask mask = 0;
  for (int i = 0; i <= n - 2; ++i) mask |= DimMask(1) << i;
  // For i <= n-2, alpha_i commutes with alpha_n (cycle constraint), so alpha_i maps n-free darts
  // to n-free darts: a boundary (n-1)-cell is a <0..n-2>-orbit made of n-free darts.
  ScopedMarker seen(g);
  std::vector<Dart> stack;
  size_t count = 0;
  g.for_each_dart([&](Dart d) {
    if (!g.is_free(n, d) || seen.test(d)) return;
    ++count;
    visit_orbit_marked(g, mask, d, seen.id(), stack, [](Dart) {});
  });
  return count;
}

std::optional<std::vector<std::pair<Dart, Dart>>> orbit_isomorphism(const Map& g,
                                                                    const OrbitType& o, Dart d,
                                                                    const Map& g2,
                                                                    const OrbitType& o2, Dart d2,
                                                                    OrbitIsoConflict* conflict) {
  require_orbit_type(g, o);
  require_orbit_type(g2, o2);
  require_dart(g, d);
  require_dart(g2, d2);
  if (o.size() != o2.size())
    throw Error(ErrorCode::Usage,
                "relabeling " + o.str() + " -> " + o2.str() + " changes the number of dimensions");
  std::unordered_map<Dart, Dart> mapd{{d, d2}}, mapr{{d2, d}};
  std::vector<std::pair<Dart, Dart>> pairs{{d, d2}};
  for (size_t head = 0; head < pairs.size(); ++head) {
    const auto [v, v2] = pairs[head];
    for (size_t p = 0; p < o.size(); ++p) {
      const Dart x = g.alpha(o[p], v);
      const Dart x2 = g2.alpha(o2[p], v2);
      auto it = mapd.find(x);
      if (it != mapd.end() && it->second != x2) {
        if (conflict) *conflict = OrbitIsoConflict{x, x2, it->second};
        return std::nullopt;
      }
      auto jt = mapr.find(x2);
      if (jt != mapr.end() && jt->second != x) {
        if (conflict) *conflict = OrbitIsoConflict{x, x2, kNoDart};
        return std::nullopt;
      }
      if (it == mapd.end()) {
        mapd.emplace(x, x2);
        mapr.emplace(x2, x);
        pairs.emplace_back(x, x2);
      }
    }
  }
  return pairs;
}

}  // namespace gmr
