#include "model/replace/query_replace.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/replace/cell_replacement.hpp"
#include "model/replace/cell_sweep.hpp"
#include "model/replace/half_cells.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/stride_prefetch.hpp"

namespace gmr::replace {

size_t QueryReplaceReport::replaced() const {
  size_t n = 0;
  for (size_t m : matched) n += m;
  return n;
}

QueryReplaceReport begin_replacement(FlaggedMap& target, const PatternStore& store, int cell_dim,
                                     Precondition precondition) {
  const Map& g = target.map;
  const int n = g.dimension();
  if (g.is_omap()) throw Error(ErrorCode::InvalidMap, "query-replace works on G-maps");
  if (cell_dim != 2 && cell_dim != 3)
    throw Error(ErrorCode::Usage, "cells are faces (2) or volumes (3)", "--cells");
  if (n != cell_dim && n != cell_dim + 1)
    throw Error(ErrorCode::InvalidMap, std::to_string(cell_dim) + "-cells are replaced in " +
                                           std::to_string(cell_dim) + "- or " +
                                           std::to_string(cell_dim + 1) + "-G-maps, not in a " +
                                           std::to_string(n) + "-G-map");
  if (precondition == Precondition::CheckValidity) {
    const ValidityReport v = check_validity(g, 1);
    if (!v.ok())
      throw Error(ErrorCode::InvalidMap, "the map is not valid: " + to_text(v.violations.front()));
  }
  target.resize_flags();
  QueryReplaceReport r;
  r.mode = store.mode();
  r.cell_dim = cell_dim;
  r.matched.assign(store.patterns().size(), 0);
  return r;
}

QueryReplaceReport query_replace(FlaggedMap& target, const PatternStore& store, int cell_dim,
                                 const std::function<void()>& after_each,
                                 const std::function<void(size_t, size_t)>& progress,
                                 const DuplicateSelector& select, const std::vector<Dart>* only,
                                 Precondition precondition) {
  QueryReplaceReport r = begin_replacement(target, store, cell_dim, precondition);
  Map& g = target.map;
  const int n = g.dimension();
  std::vector<uint8_t> positive;
  if (store.mode() == Mode::Oriented) positive = orientation_classes(g);
  const bool deferred = only || select;  // see below
  // A progress report needs the number of cells: they are listed first.
  std::vector<Dart> reps;
  if (!only && progress) {
    reps = orbit_representatives(g, cell_type(g, cell_dim));
    only = &reps;
  }
  const size_t cells = only ? only->size() : 0;
  CellSweep sweep(g, cell_dim, only);
  // A replacement relinks only its own cell's darts (and adds new ones), so the other cells'
  // boundaries are the same before and after it (cell_sweep.hpp): each cell is replaced when it
  // is looked up, its boundary still in the cache. With a list or a selector, every cell is looked
  // up first (a cell listed twice, or a selector's error, then leaves the map unchanged), the
  // matches kept as their pattern and their boundary darts in the order of the pattern's
  // template, and replaced in the order of the cells: the same result, dart for dart.
  struct Match {
    uint32_t pattern;
    size_t targets;  // offset of the cell's boundary darts in `targets`
    bool shared;     // a face of a 3-G-map with two half-faces
  };
  std::vector<Match> matches;
  std::vector<Dart> targets, f;
  BoundaryGraph c;
  std::vector<uint32_t> order;
  Word key;
  // The word the last cell was looked up by (a stored word: W(B, q) of a start dart q of its
  // patterns' boundary) and its match; `followed`: a cell's darts numbered along it.
  Word last_key;
  StoreMatch last;
  std::vector<Dart> followed;
  std::vector<uint8_t> last_in_order;  // per hit of `last`: its ranks are the identity
  CellPredictor predictor;             // the next cell along last_key fetched while one is replaced
  auto replace = [&](uint32_t pattern, const Dart* image, bool shared) {
    r.darts_added += replace_cell(target, store.replacement(pattern), image, shared);
    if (after_each) after_each();
    ++r.matched[pattern];
  };
  sweep.for_each_cell([&](Dart rep) {
    if (progress && r.cells % 4096 == 0) progress(r.cells, cells);
    ++r.cells;
    // 1. The cell's word from its first start dart, looked up (§6.3, pattern_store.hpp). First
    // against the word the previous cell matched, from rep, along which the cell is numbered
    // and checked in one pass (word_traversal.hpp): if it agrees, W(cell, rep) is that stored
    // word, so rep is a start dart (isomorphisms map start sets onto start sets; in oriented mode
    // rep must be in D+), the first in the cell's traversal order, and the lookup of its word
    // would give that match. Otherwise the cell is traversed breadth-first, its first start dart
    // found and its word looked up.
    StoreMatch match;
    uint32_t start = 0;
    const bool by_last =
        last.hits && (store.mode() == Mode::Unoriented || positive[rep]) &&
        sweep.follow(rep, last_key.data() + 1, static_cast<uint32_t>(followed.size()), target.flag,
                     followed.data());
    if (by_last) {
      match = last;
      match.start = 0;
      if (!deferred) predictor.numbered(g, cell_dim, target.flag, followed);
    } else {
      sweep.traverse(rep, target.flag, positive, c);
      start = first_start_dart(c, store.mode());
      if (start != UINT32_MAX) {
        key.assign(1, static_cast<uint32_t>(cell_dim));
        // The traversal numbered the cell breadth-first from rep: from rep, its labels are there.
        if (start == 0)
          numbered_boundary_word(c, key);
        else
          boundary_word(c, start, key, order);
        match = store.match_word(key, start);
        if (match.hits) {
          last_key = key;
          last = match;
          predictor.restart();
          followed.resize(c.size());
          last_in_order.clear();
          for (const std::vector<uint32_t>& ranks : *match.ranks) {
            bool identity = true;
            for (uint32_t k = 0; k < ranks.size(); ++k) identity &= ranks[k] == k;
            last_in_order.push_back(identity);
          }
        }
      }
    }
    const std::vector<StoreEntry>* hits = match.hits;
    if (!hits) {
      r.unmatched.push_back(rep);
      return;
    }
    size_t choice = 0;
    if (hits->size() > 1) {
      ++r.ambiguous_keys;
      if (select) choice = select(*hits, target, rep);
      if (choice >= hits->size())
        throw Error(ErrorCode::Usage,
                    "the duplicate selector chose pattern " + std::to_string(choice) + " of " +
                        std::to_string(hits->size()),
                    "dart " + std::to_string(rep));
    }
    // 2. The isomorphism f: the cell's darts in the label order of the pattern's template.
    const uint32_t pattern = static_cast<uint32_t>((*hits)[choice].pattern);
    const bool shared = n > cell_dim && !g.is_free(cell_dim + 1, rep);
    // Numbered along the pattern's own template order (ranks the identity): the numbering is f.
    if (by_last && !deferred && last_in_order[choice])
      return replace(pattern, followed.data(), shared);
    std::vector<Dart>& image = deferred ? targets : f;
    if (deferred)
      matches.push_back({pattern, targets.size(), shared});
    else
      f.clear();
    if (by_last)
      for (uint32_t k : (*match.ranks)[choice]) image.push_back(followed[k]);
    else if (start == 0)
      for (uint32_t k : (*match.ranks)[choice]) image.push_back(c.dart[k]);
    else
      for (uint32_t k : (*match.ranks)[choice]) image.push_back(c.dart[order[k]]);
    // 3. The replacement (cell_replacement.hpp).
    if (!deferred) replace(pattern, f.data(), shared);
  });
  // The deferred matches: their copies added at once (the arrays grow once), then written.
  size_t added = 0;
  for (const Match& m : matches)
    added += size_t(store.replacement(m.pattern).interior) * (m.shared ? 2 : 1);
  Dart next = added ? g.add_darts(added) : g.capacity();
  if (added) target.resize_flags();
  for (const Match& m : matches) {
    const size_t written =
        replace_cell(target, store.replacement(m.pattern), &targets[m.targets], next, m.shared);
    next += static_cast<Dart>(written);
    r.darts_added += written;
    if (after_each) after_each();
    ++r.matched[m.pattern];
  }
  if (progress) progress(r.cells, cells);
  return r;
}

namespace {

// The largest interior of the store's patterns of dimension cell_dim (0: none).
size_t largest_interior(const PatternStore& store, int cell_dim) {
  size_t most = 0;
  for (const Pattern& p : store.patterns())
    if (p.cell_dim == cell_dim) most = std::max(most, p.interior_darts.size());
  return most;
}

}  // namespace

size_t replacement_room(const Map& g, const PatternStore& store,
                        const std::vector<int>& cell_dims) {
  const bool faces = std::count(cell_dims.begin(), cell_dims.end(), 2) == 1;
  const bool volumes = std::count(cell_dims.begin(), cell_dims.end(), 3) == 1;
  const size_t most_faces = largest_interior(store, 2), most_volumes = largest_interior(store, 3);
  const bool together =
      faces && volumes && most_faces && most_volumes && !g.is_omap() && g.dimension() == 3;
  size_t room = 0;
  if (together) {
    const HalfFacesAndVolumes h = count_half_faces_and_volumes(g);
    room = h.faces * most_faces + h.volumes * most_volumes;
  }
  for (int c : cell_dims)
    if (!together || (c != 2 && c != 3)) room += replacement_room(g, store, c);
  return room;
}

size_t replacement_room_bound(size_t darts, const PatternStore& store,
                              const std::vector<int>& cell_dims) {
  size_t room = 0;
  for (int c : cell_dims) {
    const size_t most = largest_interior(store, c);
    if (most == 0) continue;
    size_t least = SIZE_MAX;
    for (const Pattern& p : store.patterns())
      if (p.cell_dim == c) least = std::min<size_t>(least, p.boundary.size());
    room += (darts + room) / least * most;
  }
  return room;
}

size_t replacement_room(const Map& g, const PatternStore& store, int cell_dim) {
  const size_t most = largest_interior(store, cell_dim);
  if (most == 0) return 0;
  const int n = g.dimension();
  if (!g.is_omap() && (cell_dim == 2 || cell_dim == 3) && (n == cell_dim || n == cell_dim + 1))
    return count_half_cells(g, cell_dim) * most;
  // Maps query_replace refuses: per cell, two half-cells when it has two.
  size_t halves = 0;
  visit_all_orbits(
      g, cell_type(g, cell_dim).mask(),
      [&](Dart d) { halves += n > cell_dim && !g.is_free(cell_dim + 1, d) ? 2 : 1; }, [](Dart) {});
  return halves * most;
}

}  // namespace gmr::replace
