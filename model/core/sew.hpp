// Checked sewing and unsewing (CGAL / Moka semantics) on n-G-maps.
//
// i-sew(d1, d2) links by alpha_i the darts of the <I>-orbits of d1 and d2, I = (0..n)\{i-1,i,i+1},
// paired by the parallel traversal of Algorithm 5 with the identity relabeling. This is exactly the
// set of alpha_i links that keeps the cycle constraint C(k,i) for |k-i| >= 2. The sew is refused
// (Error(Sew), naming the dart) when the two orbits are not isomorphic, when a dart is not i-free,
// when the orbits overlap in a way that would pair a dart with two partners, or when the result
// would not be a valid G-map. Unsewing makes the whole <I>-orbit of d i-free again.
#pragma once
#include "model/core/map.hpp"

namespace gmr {

// The orbit type (0..n)\{i-1,i,i+1} along which i-sewing propagates.
OrbitType sew_orbit_type(const Map& g, int i);

// Whether i-sew(d1,d2) is possible; when not, `why` receives the reason.
bool is_sewable(const Map& g, int i, Dart d1, Dart d2, std::string* why = nullptr);
void sew(Map& g, int i, Dart d1, Dart d2);
void unsew(Map& g, int i, Dart d);

}  // namespace gmr
