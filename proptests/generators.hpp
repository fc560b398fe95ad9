// RapidCheck generators for gmr (issue 5). Maps are described by a small `MapCase` (family,
// dimension, size, seed) built deterministically by model/random_maps.hpp: RapidCheck shrinks the
// size and the seed toward smaller maps, and a failing case prints its description, the map as
// gmr.gmap JSON and its DOT diagram (showValue below), so that every counterexample is
// reproducible from the printed seed alone.
#pragma once
#include <rapidcheck.h>

#include <ostream>
#include <string>
#include <vector>

#include "model/gmap.hpp"
#include "model/orbit_type.hpp"
#include "model/random_maps.hpp"

namespace gmr::prop {

struct MapCase {
  Generator family = Generator::SewSequence;
  int n = 2;
  size_t size = 1;  // number of cells / faces / voxels
  uint64_t seed = 0;
  GMap build() const;
  std::string str() const;
};

// A valid map of dimension n in {1,2,3} (families applicable to n), size in [1, max_size].
rc::Gen<MapCase> gen_map_case(size_t max_size = 6);
rc::Gen<MapCase> gen_map_case_of_dim(int n, size_t max_size = 6);
// Orbit types: random subsets of 0..n in increasing order.
rc::Gen<OrbitType> gen_orbit_type(int n);
// A random permutation of 0..k-1.
rc::Gen<std::vector<Dart>> gen_permutation(size_t k);

// Text for a failing case: description, JSON, DOT.
std::string describe_counterexample(const GMap& g);

}  // namespace gmr::prop

namespace rc {
template <>
struct Arbitrary<gmr::prop::MapCase> {
  static Gen<gmr::prop::MapCase> arbitrary() { return gmr::prop::gen_map_case(); }
};
}  // namespace rc

namespace gmr::prop {
inline void showValue(const MapCase& c, std::ostream& os) {
  os << c.str() << "\n" << describe_counterexample(c.build());
}
}  // namespace gmr::prop
