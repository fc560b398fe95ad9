// The graph that topological folding works on (thesis §7.2, Alg. 6, §7.3.1).
//
// A joint graph J has darts 0..N-1, each on side L (before) or R (after), with one neighbour slot
// per dimension 0..n and one κ slot. A slot may be *undefined* (kUndefined):
//  * a dimension slot is undefined for a dart whose neighbour was cut by a selection (local
//    operations, thesis §7.1.2: links to unselected darts become undefined neighbours);
//  * the κ slot is undefined for a dart that is not preserved.
// κ is undirected: kappa[x] = y iff kappa[y] = x, and it links an L dart to an R dart (the joint
// representation κ(L,R), thesis Def. 36, with one κ-arc per preserved dart pair).
//
// A single connected G-map is the joint graph with every dart on side L and no κ (folding a map,
// thesis §7.2.1). Before/after pairs are joined by a dart mapping (dart_mapping.hpp). Darts keep
// their origin (the dart index in the before or after map) for messages and for the node -> darts
// association of the inferred rules.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/elem_status.hpp"

namespace gmr::inference {

// Before (L) or after (R): the rule side, shared with rules and the checker.
using graph::Side;

// The κ "dimension" in loops over 0..n ∪ {κ}.
inline constexpr int kKappa = -1;
inline constexpr uint32_t kUndefined = UINT32_MAX;

// "0".."n" or "κ".
std::string dimension_text(int d);

class JointGraph {
 public:
  explicit JointGraph(int n) : n_(n), link_(static_cast<size_t>(n) + 1) {}

  int dimension() const { return n_; }
  size_t size() const { return side_.size(); }

  // Room for `darts` darts (no reallocation while they are added).
  void reserve(size_t darts);
  // A new dart with every slot undefined.
  uint32_t add_dart(Side side, Dart origin);
  // Sets x –d– y in both directions (d in 0..n or kKappa); x == y is a loop.
  void link(int d, uint32_t x, uint32_t y);

  uint32_t nbr(uint32_t x, int d) const { return d == kKappa ? kappa_[x] : link_[d][x]; }
  Side side(uint32_t x) const { return side_[x]; }
  Dart origin(uint32_t x) const { return origin_[x]; }
  // The dart as users see it: "7" for a single map, "before 7" / "after 12" for a pair.
  std::string describe(uint32_t x) const;
  bool has_after() const { return has_after_; }

  // Raw one-way write (tests build deliberately broken graphs with it).
  void set_nbr(uint32_t x, int d, uint32_t y) { (d == kKappa ? kappa_[x] : link_[d][x]) = y; }

 private:
  int n_;
  std::vector<std::vector<uint32_t>> link_;
  std::vector<uint32_t> kappa_;
  std::vector<Side> side_;
  std::vector<Dart> origin_;
  bool has_after_ = false;
};

// Joint-graph indices of the darts of a map: index[d] for a live dart d, kUndefined otherwise.
struct JointIndex {
  std::vector<uint32_t> before, after;
};

// The darts of g (live ones, in increasing index order) on side L, links copied, no κ.
// G-maps only (throws Error(Usage) for an O-map).
JointGraph joint_from_map(const Map& g, JointIndex* index = nullptr);

// The connected component of dart d in g (its <0..n>-orbit), as joint_from_map does for the whole
// map; index->before[e] = kUndefined for darts of other components.
JointGraph joint_from_component(const Map& g, Dart d, JointIndex* index = nullptr);

}  // namespace gmr::inference
