#include "model/replace/replace_only.hpp"

#include "model/core/error.hpp"
#include "model/replace/cell_replacement.hpp"
#include "model/replace/cell_sweep.hpp"
#include "model/replace/stride_prefetch.hpp"

namespace gmr::replace {

QueryReplaceReport replace_only(FlaggedMap& target, const PatternStore& store, size_t pattern,
                                const std::vector<Dart>* starts, Precondition precondition,
                                const std::function<void()>& after_each) {
  if (pattern >= store.patterns().size())
    throw Error(ErrorCode::Usage, "no pattern " + std::to_string(pattern) + " in a store of " +
                                      std::to_string(store.patterns().size()));
  const ReplacementTemplate& t = store.replacement(pattern);
  const int cell_dim = t.cell_dim;
  QueryReplaceReport r = begin_replacement(target, store, cell_dim, precondition);
  Map& g = target.map;
  const int n = g.dimension();
  CellSweep sweep(g, cell_dim, starts);
  // Each cell replaced when met (its boundary in the cache); with a list, every cell is checked
  // first, so that a cell listed twice leaves the map unchanged (query_replace.hpp).
  std::vector<Dart> f(t.boundary);  // the cell's boundary in label order from its dart
  BoundaryGraph c;                  // a cell that does not match: its darts, to meet them
  std::vector<Dart> pending;        // with a list: the matched cells' boundaries in label order
  std::vector<uint8_t> pending_shared;
  CellPredictor predictor;  // without a list: the next cell fetched while one is replaced
  auto replace = [&](const Dart* image, bool shared) {
    r.darts_added += replace_cell(target, t, image, shared);
    if (after_each) after_each();
    ++r.matched[pattern];
  };
  sweep.for_each_cell([&](Dart d) {
    ++r.cells;
    // The cell numbered along the pattern's word from d, checked on the way (word_traversal.hpp).
    if (!sweep.follow(d, t.word.data(), t.boundary, target.flag, f.data())) {
      sweep.traverse(d, target.flag, {}, c);
      r.unmatched.push_back(d);
      return;
    }
    const bool shared = n > cell_dim && !g.is_free(cell_dim + 1, d);
    if (!starts) {
      predictor.numbered(g, cell_dim, target.flag, f);
      return replace(f.data(), shared);
    }
    pending.insert(pending.end(), f.begin(), f.end());
    pending_shared.push_back(shared);
  });
  for (size_t m = 0; m < pending_shared.size(); ++m)
    replace(&pending[m * t.boundary], pending_shared[m]);
  return r;
}

}  // namespace gmr::replace
