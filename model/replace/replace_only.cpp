#include "model/replace/replace_only.hpp"

#include "model/core/error.hpp"
#include "model/replace/cell_replacement.hpp"
#include "model/replace/cell_sweep.hpp"

namespace gmr::replace {

namespace {

// The boundary traversed from d (local index k = label k + 1) is the pattern's boundary from its
// start: the same size, and per dart in label order the same flag and neighbour labels as the
// pattern's word W(B, start).
bool is_pattern_boundary(const BoundaryGraph& c, const ReplacementTemplate& t) {
  const uint32_t n = c.size();
  const int m = c.arity;
  if (n != t.boundary || m != t.cell_dim) return false;
  const uint32_t* w = t.word.data();
  const uint32_t* nbr = c.nbr.data();
  bool same = true;
  for (uint32_t k = 0; k < n; ++k, w += m + 1, nbr += m) {
    same &= c.flag[k] == w[0];
    for (int j = 0; j < m; ++j) same &= nbr[j] + 1 == w[1 + j];
  }
  return same;
}

}  // namespace

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
  BoundaryGraph c;
  std::vector<Dart> pending;  // with a list: the matched cells' boundaries in label order
  std::vector<uint8_t> pending_shared;
  auto replace = [&](const Dart* f, bool shared) {
    r.darts_added += replace_cell(target, t, f, shared);
    if (after_each) after_each();
    ++r.matched[pattern];
  };
  sweep.for_each_cell([&](Dart d) {
    ++r.cells;
    sweep.traverse(d, target.flag, {}, c);
    if (!is_pattern_boundary(c, t)) {
      r.unmatched.push_back(d);
      return;
    }
    const bool shared = n > cell_dim && !g.is_free(cell_dim + 1, d);
    if (!starts) return replace(c.dart.data(), shared);
    pending.insert(pending.end(), c.dart.begin(), c.dart.end());
    pending_shared.push_back(shared);
  });
  for (size_t m = 0; m < pending_shared.size(); ++m) replace(&pending[m * t.boundary], pending_shared[m]);
  return r;
}

}  // namespace gmr::replace
