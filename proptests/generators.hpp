// RapidCheck generators of maps for gmr. A map is described by a small `MapCase`
// (family, dimension, size, seed) built deterministically (model/random_maps.hpp, portable across
// standard libraries): RapidCheck shrinks the size and the seed toward smaller maps, and a failing
// case prints its description, the map as gmr.gmap JSON and its DOT diagram (showValue below), so
// that every counterexample is reproducible from the printed line alone. Corpus lines
// (proptests/corpus) are "<family> <n> <size> <seed>".
//
// Independent constructions of valid maps:
//   G-maps  glued-polygons (n >= 2), polycube (n = 3), sew-sequence (n >= 0),
//           rule-applications (n = 2, 3: a small map edited by a random sequence of checker-
//           accepted library schemes at random hooks, proptests/library.hpp);
//   O-maps  permutation-omap (n = 2: beta_1 a random permutation, beta_2 a random involution),
//           oriented (n = 2: the orientable components of glued polygons, boundary kept as beta_2
//           loops; n = 3: doubled polycubes, closed — Def. 32 O-maps have no 3-boundary).
#pragma once
#include <rapidcheck.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/core/orbit_type.hpp"
#include "model/testing/random_maps.hpp"

namespace gmr::prop {

enum class Family {
  GluedPolygons,
  Polycube,
  SewSequence,
  RuleApplications,
  PermutationOMap,
  Oriented
};
const char* to_string(Family f);
std::optional<Family> parse_family(const std::string& s);
bool is_omap_family(Family f);
// Families that build maps of dimension n (G-map or O-map ones).
std::vector<Family> families_for(int n, bool omap);

struct MapCase {
  Family family = Family::SewSequence;
  int n = 2;
  size_t size = 1;  // number of cells / faces / voxels / rule applications
  uint64_t seed = 0;
  Map build() const;
  std::string str() const;
  std::string corpus_line() const;
  static std::optional<MapCase> parse(const std::string& line);
};

// A valid G-map of dimension n in {1,2,3} (families applicable to n), size in [1, max_size].
rc::Gen<MapCase> gen_map_case(size_t max_size = 6);
rc::Gen<MapCase> gen_map_case_of_dim(int n, size_t max_size = 6);
// A valid O-map of dimension 2 or 3.
rc::Gen<MapCase> gen_omap_case(size_t max_size = 6);
rc::Gen<MapCase> gen_omap_case_of_dim(int n, size_t max_size = 6);
// Orbit types: random subsets of 0..n in increasing order.
rc::Gen<OrbitType> gen_orbit_type(int n);
// A random permutation of 0..k-1.
rc::Gen<std::vector<Dart>> gen_permutation(size_t k);

// Text for a failing case: JSON and DOT of the map.
std::string describe_counterexample(const Map& g);

inline void showValue(const MapCase& c, std::ostream& os) {
  os << c.str() << "\n" << describe_counterexample(c.build());
}

}  // namespace gmr::prop

namespace rc {
template <>
struct Arbitrary<gmr::prop::MapCase> {
  static Gen<gmr::prop::MapCase> arbitrary() { return gmr::prop::gen_map_case(); }
};
}  // namespace rc
