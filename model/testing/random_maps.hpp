// Deterministic random n-G-maps for differential tests, property tests and benchmarks.
//
// Every generator takes a std::mt19937_64 and draws from it only through `uniform` below, whose
// output is specified here (rejection sampling on the raw 64-bit words), not through
// std::uniform_int_distribution (whose algorithm is implementation-defined). The same seed
// therefore gives the same map with every compiler and standard library.
//
// Every generator returns a VALID n-G-map: it edits only through the checked operations of
// sew.hpp (sew/unsew refuse any edit that would break validity) and the builders. The maps have
// no deleted darts (dense 0..size-1) and may have several connected components unless stated.
//
// Three families:
//  * glued polygons: random polygons glued along edges by 2-sews (surfaces with boundary,
//    orientable or not);
//  * polycubes: random face-connected voxel sets -> make_polycube (3-G-maps);
//  * sew sequences: a pool of small cells (isolated edges, polygons, closed surfaces which are
//    volumes when n >= 3) edited by a random sequence of i-sews for every i in 0..n, with some
//    unsews.
// And two edits for isomorphism tests: `permute_darts` (an isomorphic copy with permuted dart ids),
// `mutate_one_link` (a guaranteed non-isomorphic valid variant), `resew_one_link` (a valid
// variant, one orbit re-glued elsewhere, isomorphic or not: hard cases for isomorphism tests).
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "model/core/builders.hpp"
#include "model/core/map.hpp"

namespace gmr::testing {

using Rng = std::mt19937_64;

// Uniform integer in [lo, hi] (lo <= hi), portable across standard libraries.
uint64_t uniform(Rng& rng, uint64_t lo, uint64_t hi);
// True with probability percent/100.
bool chance(Rng& rng, unsigned percent);
// A uniformly random permutation of 0..n-1 (Fisher-Yates with `uniform`).
std::vector<Dart> random_permutation(Rng& rng, size_t n);

// --- generators ----------------------------------------------------------------------------

struct GluedPolygonsOptions {
  int n = 2;                             // dimension of the G-map, >= 2
  size_t min_faces = 1, max_faces = 10;  // number of polygons, uniform in the range
  size_t min_sides = 1, max_sides = 6;   // sides of each polygon, uniform in the range (>= 1)
  // Glue every new polygon to an earlier one by one 2-sew (a spanning tree) before the extra
  // sews. The result is connected whenever min_sides >= 2 (each polygon then keeps a free edge
  // for the next one); with 1-gons, a polygon that finds no free edge starts a new component.
  bool connected = true;
  size_t max_extra_sews = 8;  // extra random 2-sew attempts, count uniform in [0, max]
};
Map random_glued_polygons(Rng& rng, const GluedPolygonsOptions& opt = {});

// `count` distinct voxels, face-connected, grown from (0,0,0) by random face neighbours.
std::vector<Voxel> random_voxels(Rng& rng, size_t count);

struct PolycubeOptions {
  size_t min_voxels = 1, max_voxels = 6;
};
// A connected polycube 3-G-map (48 darts per voxel).
Map random_polycube(Rng& rng, const PolycubeOptions& opt = {});

struct SewSequenceOptions {
  int n = 2;                            // dimension, >= 0
  size_t min_cells = 1, max_cells = 6;  // pool size, uniform in the range
  // Pool cells (each uniformly among those that fit the dimension): an isolated dart, an isolated
  // edge (n >= 0); a k-gon, k in 1..5 (n >= 1); a tetrahedron, square pyramid or cube surface
  // (n >= 2; a volume when n >= 3).
  size_t steps = 16;            // sew/unsew operations attempted
  unsigned unsew_percent = 15;  // chance that a step unsews (when something is sewn)
  size_t tries = 24;            // random dart pairs tried for one sew before giving up the step
};
Map random_sewn_cells(Rng& rng, const SewSequenceOptions& opt = {});

enum class Generator { GluedPolygons, Polycube, SewSequence };
const char* to_string(Generator g);
// Generators applicable to dimension n: GluedPolygons (n >= 2), Polycube (n == 3),
// SewSequence (n >= 0).
std::vector<Generator> generators_for(int n);
// One map of the given family with default options (Polycube requires n == 3).
Map random_map(Rng& rng, Generator gen, int n);

// --- random O-maps (Def. 32: beta_1 a permutation, beta_2..n involutions, cycle constraint on
// (1..n)_{+2}) -------------------------------------------------------------------------------

struct PermutationOMapOptions {
  size_t min_darts = 1, max_darts = 12;  // number of darts, uniform in the range
  unsigned loop_percent = 25;            // chance that a dart stays 2-free (a 2-loop: boundary)
};
// A 2-O-map drawn directly: beta_1 a uniformly random permutation (its cycles are the oriented
// faces), beta_2 a random involution with ~loop_percent fixed points. For n = 2 there is no cycle
// constraint on O-maps, so every such pair is a valid 2-O-map (possibly several components).
Map random_permutation_omap(Rng& rng, const PermutationOMapOptions& opt = {});

// The double of g along its boundary: g, a copy of g, and every n-free dart n-sewn to its copy
// (a closed n-G-map; valid because the boundary of a valid G-map is closed under alpha_0..n-2).
// Orientable when g is. Used to build closed volumes (n = 3) for random O-maps.
Map double_along_boundary(const Map& g);

// The O-maps of the orientable components of g (orient(g, d, keep_boundary = true) on one dart
// per component), as one O-map; components that cannot be oriented (not orientable, or with 0- or
// 1-free darts, or 3-free ones) are skipped. Used on random glued polygons (n = 2) and doubled
// polycubes (n = 3).
Map oriented_components(const Map& g);

// --- edits ---------------------------------------------------------------------------------

// An isomorphic copy of g with dart d renamed perm[d]. perm must be a permutation of
// 0..capacity()-1 (else Error(Usage)); alpha'_i(perm[d]) = perm[alpha_i(d)], deleted darts of g
// are deleted in the copy (at their new index). Kind and dimension are kept. Works for O-maps.
Map permute_darts(const Map& g, const std::vector<Dart>& perm);

struct Mutation {
  enum class Kind { None, Unsew, Sew, Resew };
  Kind kind = Kind::None;
  int dim = -1;
  Dart dart = kNoDart;     // Unsew: a dart of the unsewn orbit; Sew/Resew: first sewn dart
  Dart partner = kNoDart;  // Unsew: its former partner; Sew/Resew: second sewn dart
  std::string str() const;
};

// Changes the links of one i-sew orbit of a G-map (not an O-map: Error(Usage)).
//  * If some dart is not free in some dimension: picks such a (dimension i, dart) uniformly among
//    all of them and i-unsews it (Kind::Unsew).
//  * Otherwise (every dart free in every dimension) and size >= 2: i-sews two distinct random
//    darts for a random i (Kind::Sew).
//  * Otherwise (0 or 1 dart): Kind::None, g unchanged.
// Guarantees, when g is a valid G-map: g stays valid, keeps its darts, and the number of i-free
// darts (i = result.dim) strictly changes, so the result is NOT isomorphic to the input (every
// isomorphism preserves the number of i-free darts for each i).
Mutation mutate_one_link(Map& g, Rng& rng);

// i-unsews a random sewn orbit and i-sews one of its darts to a different i-free dart (possibly
// of the same orbit it was sewn to, in another pairing: a flipped gluing), trying up to `tries`
// partners; when none is sewable, the original sew is restored and Kind::None is returned.
// Guarantees: g stays valid and keeps its darts. The result may or may not be isomorphic to the
// input — it keeps most cheap invariants, which makes it a hard case for isomorphism tests.
Mutation resew_one_link(Map& g, Rng& rng, size_t tries = 64);

}  // namespace gmr::testing
