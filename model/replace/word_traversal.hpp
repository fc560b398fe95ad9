// A cell's boundary traversed along a known word (Damiand & Nivoliers 2022, Alg. 1 and Theorem 1,
// read backwards). W(B, s) lists, per dart in label order, its flag and the labels of its
// neighbours, a new neighbour taking the next label (flagged_word.hpp). Given such a word and a
// dart d of a target, the darts of d's <0..i-1>-orbit are numbered by following the word: the dart
// of label 1 is d; for the k-th labelled dart x and j = 0..i-1, the word's letter is either the
// next label (alpha_j(x) is numbered with it) or a label already given, which alpha_j(x) must
// carry. The flags are compared on the way. When every letter agrees, the numbering is a
// homomorphism of the word's boundary graph onto d's orbit (its image is closed under
// alpha_0..alpha_{i-1}); with every dart numbered once (a per-dart bit, the map's darts met so far)
// it is a bijection: the word from d is W(B, s), so the orbit is isomorphic to B with d sent to s
// (Theorem 1), and the k-th numbered dart is the image of B's k-th labelled dart. No local index
// array, no neighbour table: one pass over the orbit, reading each dart's links once, and the check
// is the traversal itself.
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::replace {

// The per-dart bits of the darts met (bit x % 64 of word x / 64), sized to the darts swept.
struct MetBits {
  uint64_t* bits = nullptr;
  Dart size = 0;
  bool test(Dart x) const { return bits[x >> 6] >> (x & 63) & 1; }
  void set(Dart x) const { bits[x >> 6] |= uint64_t(1) << (x & 63); }
  void reset(Dart x) const { bits[x >> 6] &= ~(uint64_t(1) << (x & 63)); }
  // The first dart x >= from whose bit is clear (size when none): the met darts skipped a word
  // at a time.
  Dart next_clear(Dart from) const {
    if (from >= size) return size;
    size_t w = from >> 6;
    uint64_t clear = ~bits[w] & (~uint64_t(0) << (from & 63));
    const size_t last = (size_t(size) - 1) >> 6;
    while (clear == 0) {
      if (++w > last) return size;
      clear = ~bits[w];
    }
    const Dart x = static_cast<Dart>((w << 6) + static_cast<size_t>(__builtin_ctzll(clear)));
    return x < size ? x : size;
  }
};

// Follows `word` (per dart in label order: its flag, then the labels 1..size of its i neighbours
// alpha_0..alpha_{i-1}) from d through the <0..i-1>-orbit of d in g. On success returns true,
// out[k] being the dart of label k + 1 (out has room for `size` darts) and every dart of the orbit
// set in `met`. On the first disagreement (a flag, a neighbour, a dart numbered twice or met
// before, a dart outside `met`) returns false with `met` as it was. d must be alive and not met.
// `flag` is indexed by dart (a dart past its end is unflagged).
bool follow_word(const Map& g, int i, Dart d, const uint32_t* word, uint32_t size,
                 const std::vector<uint32_t>& flag, MetBits met, Dart* out);

}  // namespace gmr::replace
