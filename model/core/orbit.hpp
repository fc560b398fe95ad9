// Orbits (thesis Def. 56, Algorithm 4) and orbit isomorphism up to a relabeling (Algorithm 5).
//
// The <o>-orbit of a dart d is the set of darts reachable from d through links whose dimension is
// in <o>. For an O-map, beta_1 is a permutation of a finite set, so forward reachability along
// beta_1 already gives the whole cycle; the traversal never needs beta_1^{-1}.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "model/core/map.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr {

// Checks that every dimension of `o` exists in `g` and that `o` has no `_`; throws Error(Range).
void require_orbit_type(const Map& g, const OrbitType& o);

// Algorithm 4: the darts of the <o>-orbit of d, in BFS order (d first, links visited in the order
// of `o`).
std::vector<Dart> orbit(const Map& g, const OrbitType& o, Dart d);

namespace detail {
// The traversal of visit_orbit_marked on raw arrays: link[p] is the link array of the p-th
// dimension of the mask (increasing), K their number (0: runtime count k).
// The last neighbour found is kept in a register instead of being pushed and popped at once (the
// visiting order is the one of the plain stack DFS), and a neighbour equal to the current or the
// previously visited dart is known to be marked without reading the marker.
template <int K, class F>
size_t visit_orbit_raw(const Dart* const* link, int k, uint64_t* words, Dart cap, Dart d,
                       std::vector<Dart>& stack, F& f) {
  const int kk = K ? K : k;
  size_t top = 0, count = 0;
  words[d >> 6] |= uint64_t(1) << (d & 63);
  Dart v = d, u = d;  // u: the dart visited before v
  for (;;) {
    f(v);
    ++count;
    Dart next = kNoDart;
    for (int p = 0; p < kk; ++p) {
      const Dart w = link[p][v];
      if (w == v || w == u) continue;  // visited, hence marked
      if (w >= cap) continue;          // dangling link of an invalid map: not a dart
      uint64_t& word = words[w >> 6];
      const uint64_t bit = uint64_t(1) << (w & 63);
      if (word & bit) continue;
      word |= bit;
      if (next != kNoDart) {
        if (top == stack.size()) stack.resize(top < 16 ? 16 : 2 * top);
        stack[top++] = next;
      }
      next = w;
    }
    u = v;
    if (next != kNoDart)
      v = next;
    else if (top)
      v = stack[--top];
    else
      break;
  }
  return count;
}

// Two dimensions (a < b): in a G-map, <a,b>-orbits are paths or cycles, and the stack DFS walks
// them: a dart v reached from the previously visited u by link y has link[y][v] == u, so its only
// candidate is link[1-y][v]. This fast path takes that step with predictable branches; any other
// situation (the start, a dart popped from the stack, a non-involutive link) takes the general
// step of visit_orbit_raw. Same visiting order as visit_orbit_raw.
template <class F>
size_t visit_orbit_raw2(const Dart* const* link, uint64_t* words, Dart cap, Dart d,
                        std::vector<Dart>& stack, F& f) {
  const Dart* const l0 = link[0];
  const Dart* const l1 = link[1];
  // Marks w and returns it when it is a dart not yet marked; kNoDart otherwise.
  auto take = [words, cap](Dart w) -> Dart {
    if (w >= cap) return kNoDart;  // dangling link of an invalid map: not a dart
    uint64_t& word = words[w >> 6];
    const uint64_t bit = uint64_t(1) << (w & 63);
    if (word & bit) return kNoDart;
    word |= bit;
    return w;
  };
  size_t top = 0, count = 0;
  words[d >> 6] |= uint64_t(1) << (d & 63);
  Dart v = d, u = d;
  int y = -1;  // the link (0 or 1) by which v was reached from u; -1: unknown
  for (;;) {
    f(v);
    ++count;
    Dart next;
    int ny;
    if (y == 0 && l0[v] == u) {
      next = take(l1[v]);
      ny = 1;
    } else if (y == 1 && l1[v] == u) {
      next = take(l0[v]);
      ny = 0;
    } else {
      // General step: both links, in order; the first new one is pushed when there are two.
      const Dart w0 = l0[v], w1 = l1[v];
      const Dart n0 = (w0 == v || w0 == u || w0 == d) ? kNoDart : take(w0);  // v, u, d: marked
      const Dart n1 = (w1 == v || w1 == u || w1 == d) ? kNoDart : take(w1);
      if (n1 != kNoDart) {
        if (n0 != kNoDart) {
          if (top == stack.size()) stack.resize(top < 16 ? 16 : 2 * top);
          stack[top++] = n0;
        }
        next = n1;
        ny = 1;
      } else {
        next = n0;
        ny = 0;
      }
    }
    u = v;
    if (next != kNoDart) {
      v = next;
      y = ny;
    } else if (top) {
      v = stack[--top];
      y = -1;
    } else {
      break;
    }
  }
  return count;
}
}  // namespace detail

// Visits the <mask>-orbit of d using marker m, leaving every visited dart marked (so that a caller
// can iterate over all orbits of a type with one marker). `stack` is scratch space (its contents
// on return are unspecified). Returns the number of darts visited.
// Order: depth-first — pop a dart, visit it, push its unmarked neighbours in increasing dimension
// order. A link to a non-existent index (dangling link of an invalid map) is not followed.
// The mask's dimensions must be dimensions of g (see require_orbit_type).
template <class F>
size_t visit_orbit_marked(const Map& g, DimMask mask, Dart d, int m, std::vector<Dart>& stack,
                          F&& f) {
  // Hot loop on raw arrays: the link arrays of the mask's dimensions and the marker's words are
  // hoisted out of the loop (no per-step vector-of-vector indirection).
  const Dart* link[kMaxDim];
  int k = 0;
  for (DimMask rest = mask; rest; rest &= rest - 1) link[k++] = g.links(__builtin_ctz(rest)).data();
  uint64_t* const words = g.marker_bits(m).data();
  const Dart cap = g.capacity();
  switch (k) {
    case 1:
      return detail::visit_orbit_raw<1>(link, k, words, cap, d, stack, f);
    case 2:
      return detail::visit_orbit_raw2(link, words, cap, d, stack, f);
    case 3:
      return detail::visit_orbit_raw<3>(link, k, words, cap, d, stack, f);
    default:
      return detail::visit_orbit_raw<0>(link, k, words, cap, d, stack, f);
  }
}

// Visits every <mask>-orbit of g once, with a marker of its own: on_orbit(r) for the orbit's
// smallest dart r (orbits are met in increasing order of r), then on_dart(x) for each of its
// darts in visit_orbit_marked order. Returns the number of orbits. Without deleted darts, the
// scan for the next unmarked dart skips 64 marked darts at a time.
template <class R, class F>
size_t visit_all_orbits(const Map& g, DimMask mask, R&& on_orbit, F&& on_dart) {
  ScopedMarker seen(g);
  std::vector<Dart> stack;
  size_t n = 0;
  if (g.has_holes()) {
    g.for_each_dart([&](Dart d) {
      if (seen.test(d)) return;
      ++n;
      on_orbit(d);
      visit_orbit_marked(g, mask, d, seen.id(), stack, on_dart);
    });
    return n;
  }
  const uint64_t* const words = g.marker_bits(seen.id()).data();
  const Dart cap = g.capacity();
  const size_t nw = (size_t(cap) + 63) / 64;
  for (size_t wi = 0; wi < nw; ++wi) {
    const uint64_t valid =
        (wi + 1 < nw || cap % 64 == 0) ? ~uint64_t(0) : (uint64_t(1) << (cap % 64)) - 1;
    // Re-read the word after each orbit: the visit marks darts further on.
    for (uint64_t todo; (todo = ~words[wi] & valid) != 0;) {
      const Dart d = static_cast<Dart>(wi * 64 + static_cast<size_t>(__builtin_ctzll(todo)));
      ++n;
      on_orbit(d);
      visit_orbit_marked(g, mask, d, seen.id(), stack, on_dart);
    }
  }
  return n;
}

// Number of <o>-orbits of g.
size_t count_orbits(const Map& g, const OrbitType& o);
// One representative dart per <o>-orbit, in increasing dart order.
std::vector<Dart> orbit_representatives(const Map& g, const OrbitType& o);

// The orbit type of i-cells: (lowest..n)\{i} (G-maps, and O-maps for i >= 1).
OrbitType cell_type(const Map& g, int i);
// Number of i-cells. For an O-map, 0-cells (vertices) are orbits of {beta_k o beta_1 | 2<=k<=n}
// (thesis §1.4).
size_t count_cells(const Map& g, int i);
// counts[i] = number of i-cells, i = 0..n.
std::vector<size_t> count_all_cells(const Map& g);
// sum_i (-1)^i c_i.
long long euler_characteristic(const Map& g);
// Connected components: <lowest..n>-orbits.
size_t count_components(const Map& g);
// The darts of the O-map vertex (0-cell) of d.
std::vector<Dart> omap_vertex(const Map& g, Dart d);

// Boundary detection. A dart is i-free if it carries an i-loop; the boundary of an n-G-map is the
// set of n-free darts (an O-map of this library has no boundary: its n-loops, if any, are
// reported).
std::vector<Dart> free_darts(const Map& g, int i);
bool is_closed(const Map& g);  // no n-free dart
// Number of boundary (n-1)-cells: orbits of type <0..n-2> among n-free darts (the boundary's faces
// in 3D, edges in 2D).
size_t count_boundary_cells(const Map& g);

// Algorithm 5: isomorphism of the <o>-orbit of d in g with the <o2>-orbit of d2 in g2, where
// dimension o[p] corresponds to o2[p] (positional relabeling). Returns the dart pairs (x, x') in
// BFS order (positions p in increasing order at each dart), or nullopt when the orbits are not
// isomorphic. o and o2 must have equal sizes and no `_`. An already-mapped dart is not enqueued
// again. Cost O(|orbit| · |o|) expected (hash maps).
// When not isomorphic and `conflict` is given, it receives the first pair (x, x2) of the joint BFS
// that cannot be added: either x already has the image `earlier` != x2, or (earlier == kNoDart) x2
// is already the image of another dart.
struct OrbitIsoConflict {
  Dart x = kNoDart, x2 = kNoDart, earlier = kNoDart;
};
std::optional<std::vector<std::pair<Dart, Dart>>> orbit_isomorphism(
    const Map& g, const OrbitType& o, Dart d, const Map& g2, const OrbitType& o2, Dart d2,
    OrbitIsoConflict* conflict = nullptr);

}  // namespace gmr
