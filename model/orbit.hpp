// Orbits (thesis Def. 56, Algorithm 4) and orbit isomorphism up to a relabeling (Algorithm 5).
//
// The <o>-orbit of a dart d is the set of darts reachable from d through links whose dimension is in
// <o>. For an O-map, beta_1 is a permutation of a finite set, so forward reachability along beta_1
// already gives the whole cycle; the traversal never needs beta_1^{-1}.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "model/gmap.hpp"
#include "model/orbit_type.hpp"

namespace gmr {

// Checks that every dimension of `o` exists in `g` and that `o` has no `_`; throws Error(Range).
void require_orbit_type(const GMap& g, const OrbitType& o);

// Algorithm 4: the darts of the <o>-orbit of d, in BFS order (d first, links visited in the order
// of `o`).
std::vector<Dart> orbit(const GMap& g, const OrbitType& o, Dart d);

// Visits the <mask>-orbit of d using marker m, leaving every visited dart marked (so that a caller
// can iterate over all orbits of a type with one marker). `stack` is scratch space. Returns the
// number of darts visited.
template <class F>
size_t visit_orbit_marked(const GMap& g, DimMask mask, Dart d, int m, std::vector<Dart>& stack,
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
    for (DimMask rest = mask; rest; rest &= rest - 1) {
      const int i = __builtin_ctz(rest);
      const Dart w = g.alpha(i, v);
      if (!g.is_marked(w, m)) {
        g.mark(w, m);
        stack.push_back(w);
      }
    }
  }
  return count;
}

// Number of <o>-orbits of g.
size_t count_orbits(const GMap& g, const OrbitType& o);
// One representative dart per <o>-orbit, in increasing dart order.
std::vector<Dart> orbit_representatives(const GMap& g, const OrbitType& o);

// The orbit type of i-cells: (lowest..n)\{i} (G-maps, and O-maps for i >= 1).
OrbitType cell_type(const GMap& g, int i);
// Number of i-cells. For an O-map, 0-cells (vertices) are orbits of {beta_k o beta_1 | 2<=k<=n}
// (thesis §1.4 of the digest).
size_t count_cells(const GMap& g, int i);
// counts[i] = number of i-cells, i = 0..n.
std::vector<size_t> count_all_cells(const GMap& g);
// sum_i (-1)^i c_i.
long long euler_characteristic(const GMap& g);
// Connected components: <lowest..n>-orbits.
size_t count_components(const GMap& g);
// The darts of the O-map vertex (0-cell) of d.
std::vector<Dart> omap_vertex(const GMap& g, Dart d);

// Boundary detection. A dart is i-free if it carries an i-loop; the boundary of an n-G-map is the
// set of n-free darts (an O-map of this library has no boundary: its n-loops, if any, are reported).
std::vector<Dart> free_darts(const GMap& g, int i);
bool is_closed(const GMap& g);  // no n-free dart
// Number of boundary (n-1)-cells: orbits of type <0..n-2> among n-free darts (the boundary's faces
// in 3D, edges in 2D).
size_t count_boundary_cells(const GMap& g);

// Algorithm 5: isomorphism of the <o>-orbit of d in g with the <o2>-orbit of d2 in g2, where
// dimension o[p] corresponds to o2[p] (positional relabeling). Returns the dart pairs (x, x') in BFS
// order, or nullopt when the orbits are not isomorphic. o and o2 must have equal sizes and no `_`.
// (Digest [D] guard: an already-mapped dart is not enqueued again.)
std::optional<std::vector<std::pair<Dart, Dart>>> orbit_isomorphism(const GMap& g,
                                                                     const OrbitType& o, Dart d,
                                                                     const GMap& g2,
                                                                     const OrbitType& o2, Dart d2);

}  // namespace gmr
