// The boundary of a cell or of a pattern as a local graph (Damiand & Nivoliers 2022, §4.2–4.3,
// lifted to G-maps): darts 0..size-1 with m+1 neighbour functions, an optional flag per dart and
// the orientation class of each dart.
//  * a face (half-face, <0,1>-orbit) of a target: neighbours alpha_0, alpha_1 (m = 1);
//  * a volume (<0,1,2>-orbit) of a target: alpha_0, alpha_1, alpha_2 (m = 2);
//  * an f-pattern (2-G-map disc): the 2-free darts B with alpha_0 and the boundary successor
//    abar_1(d) = alpha_1 (alpha_2 alpha_1)^j (d), j >= 0 smallest with a 2-free result (§4.2.1);
//  * a v-pattern (3-G-map ball): the 3-free darts with alpha_0, alpha_1 and
//    abar_2(d) = alpha_2 (alpha_3 alpha_2)^j (d), j >= 0 smallest (Def. 6, read with j >= 0).
// In each case the neighbours are involutions on the boundary darts, so Theorem 1 applies.
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::replace {

struct BoundaryGraph {
  int arity = 0;                  // m + 1
  std::vector<Dart> dart;         // local index -> dart of the map
  std::vector<uint32_t> nbr;      // nbr[k * arity + j]: local index of the j-th neighbour of k
  std::vector<uint32_t> flag;     // per local dart (0: unflagged)
  std::vector<uint8_t> positive;  // per local dart: 1 if in the orientation class D+

  uint32_t size() const { return static_cast<uint32_t>(dart.size()); }
  uint32_t neighbour(uint32_t k, int j) const { return nbr[size_t(k) * arity + j]; }
};

// The boundary successor used for dimension i of a pattern boundary (Damiand & Nivoliers §4.2.1).
Dart boundary_successor(const Map& g, int i, Dart d);

// `flag` and `positive` are indexed by dart (positive may be empty: every dart positive).
// The i-cell orbit <0..i-1> of d of a target map (a half-face for i = 2, a volume for i = 3).
BoundaryGraph cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                            const std::vector<uint8_t>& positive);
// The same into `out`, whose arrays are reused (no allocation once they are large enough).
void cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                   const std::vector<uint8_t>& positive, BoundaryGraph& out);
// The same, numbering the orbit's darts in `local` (indexed by dart, UINT32_MAX for every dart of
// the orbit on entry): local[x] is the local index of x on return, left for the caller to reset.
void cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                   const std::vector<uint8_t>& positive, std::vector<uint32_t>& local,
                   BoundaryGraph& out);
// The n-free darts of an n-G-map pattern (its boundary), neighbours alpha_0..alpha_{n-2} and the
// boundary successor for n-1.
BoundaryGraph pattern_boundary(const Map& p, const std::vector<uint32_t>& flag,
                               const std::vector<uint8_t>& positive);

// Whether the local graph is connected.
bool is_connected(const BoundaryGraph& b);

}  // namespace gmr::replace
