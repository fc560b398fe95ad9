// Canonical forms: BFS-word signatures (Gosselin et al., summarised in Damiand & Nivoliers 2022
// §2.4, Algorithm 1, Defs. 3–5), lifted from combinatorial maps to G-maps and O-maps:
//  * labels: the start dart gets 1, then darts get 2, 3, ... in BFS discovery order, links visited
//    in increasing dimension order (alpha_0, alpha_1, ..., alpha_n);
//  * a G-map has no epsilon (free darts are loops), so the word W(M,d) lists, for the darts in
//    label order, the labels of alpha_lo(d_k), ..., alpha_n(d_k);
//  * flags (Damiand & Nivoliers §4.3): an optional per-dart value appended in label order.
// The signature of a connected map is the lexicographically smallest word over all start darts
// (O(|D|^2)); a map with several components is signed by the sorted list of its components'
// signatures. Two maps are isomorphic iff their signatures are equal (Theorem 1).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "model/core/map.hpp"

namespace gmr {

using Word = std::vector<uint32_t>;

struct Signature {
  int n = 0;
  MapKind kind = MapKind::GMap;
  std::vector<Word> components;  // sorted; each = word followed by the flags in label order
  friend bool operator==(const Signature&, const Signature&) = default;
  friend auto operator<=>(const Signature&, const Signature&) = default;
  std::string str() const;  // compact text form (for hashing and display)
};

// W(M,d) on the connected component of d; `flags` (optional, indexed by dart) are appended.
Word bfs_word(const Map& g, Dart d, const std::vector<uint32_t>* flags = nullptr);
// Labels of Algorithm 1: order[k] = the dart labelled k+1.
std::vector<Dart> bfs_labeling(const Map& g, Dart d);
// Minimal word over all darts of the component of d.
Word component_signature(const Map& g, Dart d, const std::vector<uint32_t>* flags = nullptr);
Signature signature(const Map& g, const std::vector<uint32_t>* flags = nullptr);

// Isomorphism of two maps (same kind and dimension), preserving flags when given.
// Connected case: fixes a start dart in g and tries every start dart in h (Theorem 1), stopping at
// the first mismatch of each word. Several components: compares signatures.
bool is_isomorphic(const Map& g, const Map& h, const std::vector<uint32_t>* flags_g = nullptr,
                   const std::vector<uint32_t>* flags_h = nullptr);

}  // namespace gmr
