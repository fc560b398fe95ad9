// A prefetch hint for the next cell a sweep numbers along a known word (word_traversal.hpp). Along
// a word, the k-th numbered dart of a cell is the dart of label k + 1, so the cells met one after
// the other by the same word have their darts in corresponding places: on a structured mesh, where
// a sweep meets cells at regular steps through each generation of darts (the input's, then those
// each earlier step appended), label k's dart advances by the same stride from cell to cell. The
// next cell's darts are then predicted as last[k] + (last[k] - before[k]) from the last two cells,
// and their links and flags fetched into the cache while the last cell is replaced. Following the
// word otherwise waits on each region of the next cell in turn (a dart's neighbours are known only
// once its links arrive), which is most of a traversal's time on cells whose darts lie in several
// regions (a volume after its faces were replaced). A wrong prediction costs only the fetches.
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::replace {

// Whether sweeps predict cells of dimension i. Measured on the hexahedral subdivision
// (docs/query-replace.md, Performance): volumes, whose darts lie in the regions of three
// generations, were followed about 15 % faster (the step alone, alternated processes; the whole
// sequence measured in one process, the prefetch switched iteration by iteration, is within 2 %
// with or without it); faces, whose darts there lie in two runs the processor's own stream
// prefetch already follows, about 10 % slower (the fetches cost more than they save), so faces
// are not predicted.
inline bool predicts_cells(int i) { return i == 3; }

// last, before: the darts of the last two cells numbered along the same word (size each), i = 2 or
// 3. Fetches alpha_0..alpha_{i-1} and the flag of the predicted dart of every second label.
void prefetch_predicted_cell(const Map& g, int i, const std::vector<uint32_t>& flag,
                             const Dart* last, const Dart* before, uint32_t size);

// The cells a sweep numbers along one word, one after the other: from the second on, each one
// numbered fetches the next one's predicted darts (for the dimensions predicts_cells allows).
class CellPredictor {
 public:
  // A cell of dimension i numbered along the word (its darts in label order).
  void numbered(const Map& g, int i, const std::vector<uint32_t>& flag,
                const std::vector<Dart>& cell) {
    if (!predicts_cells(i)) return;
    if (known_)
      prefetch_predicted_cell(g, i, flag, cell.data(), before_.data(),
                              static_cast<uint32_t>(cell.size()));
    before_ = cell;
    known_ = true;
  }
  // The next cell follows another word: nothing to predict from until two are numbered.
  void restart() { known_ = false; }

 private:
  std::vector<Dart> before_;
  bool known_ = false;
};

}  // namespace gmr::replace
