// The cells of a target met one after the other, each once (query_replace.hpp, replace_only.hpp;
// Damiand & Nivoliers 2022 §6.3). An i-cell is a half-face (<0,1>-orbit) for i = 2 or a volume
// (<0,1,2>-orbit) for i = 3; a face of a 3-G-map has two half-faces and is met once, at the
// half-face of its first dart. Without a list, the cells are met by one sweep over the darts, each
// at its smallest dart: a bit per dart (kept over the sweep, cleared once at the end) marks the
// darts of the cells met, so a dart whose bit is set is skipped. With a list (one dart per cell),
// the cells are met in its order and a cell named twice is refused.
// A met cell's boundary is numbered from its dart either by a breadth-first traversal
// (cell_boundary) or along a known word (follow_word, word_traversal.hpp), which numbers and checks
// it in one pass when the cell is expected to match one pattern.
// Replacing a met cell does not change the cells still to come (a replacement relinks only its
// cell's darts and adds new ones after the darts swept), so a caller may replace each cell when it
// is met.
#pragma once
#include <vector>

#include "model/replace/boundary_graph.hpp"
#include "model/replace/word_traversal.hpp"

namespace gmr::replace {

class CellSweep {
 public:
  // Throws Error(Usage) for a listed dart that is not alive.
  CellSweep(const Map& g, int cell_dim, const std::vector<Dart>* only);
  ~CellSweep();
  CellSweep(const CellSweep&) = delete;
  CellSweep& operator=(const CellSweep&) = delete;

  // Calls visit(d) for every cell, d its smallest or its listed dart; a listed cell already met
  // is Error(Usage) ("a cell is listed twice").
  template <class F>
  void for_each_cell(F&& visit) {
    if (only_) {
      for (Dart d : *only_) {
        if (met_.test(d)) throw_listed_twice(d);
        visit(d);
      }
      return;
    }
    for (Dart d = met_.next_clear(0); d < capacity_; d = met_.next_clear(d + 1))
      if (g_.alive(d)) visit(d);
  }
  // The boundary of d's cell numbered by a breadth-first traversal from d (cell_boundary: local
  // index k is d's label k + 1 in the word from d, flagged_word.hpp); the cell is marked met, and
  // for a face of a 3-G-map its other half-face too.
  void traverse(Dart d, const std::vector<uint32_t>& flag, const std::vector<uint8_t>& positive,
                BoundaryGraph& out);
  // The boundary of d's cell numbered along `word` (follow_word: `size` darts, out[k] of label
  // k + 1): on success the cell is marked met as by traverse and true is returned; otherwise
  // nothing is marked (traverse then meets the cell).
  bool follow(Dart d, const uint32_t* word, uint32_t size, const std::vector<uint32_t>& flag,
              Dart* out);

 private:
  [[noreturn]] static void throw_listed_twice(Dart d);
  // The cell's darts out[0..count) are met: with a list, remembered for the reset; for a face of
  // a 3-G-map, its other half-face marked too.
  void meet(const Dart* darts, size_t count);
  const Map& g_;
  int cell_dim_;
  const std::vector<Dart>* only_;
  Dart capacity_;
  MetBits met_;
  std::vector<Dart> listed_;  // with a list: the darts to reset
};

}  // namespace gmr::replace
