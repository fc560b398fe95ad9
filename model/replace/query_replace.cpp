#include "model/replace/query_replace.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/replace/cell_replacement.hpp"
#include "model/replace/orientation.hpp"

namespace gmr::replace {

size_t QueryReplaceReport::replaced() const {
  size_t n = 0;
  for (size_t m : matched) n += m;
  return n;
}

QueryReplaceReport query_replace(FlaggedMap& target, const PatternStore& store, int cell_dim,
                                 const std::function<void()>& after_each,
                                 const std::function<void(size_t, size_t)>& progress,
                                 const DuplicateSelector& select, const std::vector<Dart>* only,
                                 Precondition precondition) {
  Map& g = target.map;
  const int n = g.dimension();
  if (g.is_omap()) throw Error(ErrorCode::InvalidMap, "query-replace works on G-maps");
  if (cell_dim != 2 && cell_dim != 3) throw Error(ErrorCode::Usage, "cells are faces (2) or volumes (3)", "--cells");
  if (n != cell_dim && n != cell_dim + 1)
    throw Error(ErrorCode::InvalidMap, std::to_string(cell_dim) + "-cells are replaced in " + std::to_string(cell_dim) +
                                           "- or " + std::to_string(cell_dim + 1) + "-G-maps, not in a " +
                                           std::to_string(n) + "-G-map");
  if (precondition == Precondition::CheckValidity) {
    const ValidityReport v = check_validity(g, 1);
    if (!v.ok()) throw Error(ErrorCode::InvalidMap, "the map is not valid: " + v.violations.front().describe());
  }
  target.resize_flags();
  QueryReplaceReport r;
  r.mode = store.mode();
  r.cell_dim = cell_dim;
  r.matched.assign(store.patterns().size(), 0);
  std::vector<uint8_t> positive;
  if (store.mode() == Mode::Oriented) positive = orientation_classes(g);
  // A face of a 3-G-map is a <0,1,3>-orbit; a volume a <0,1,2>-orbit; faces of 2-G-maps <0,1>.
  // The cells are met by one sweep over the darts (each cell at its smallest dart, in increasing
  // order, as orbit_representatives lists them), their darts marked when examined; a list of cells
  // (`only`), or a progress report that needs the number of cells, are listed first.
  std::vector<Dart> reps;
  if (only) reps = *only;
  else if (progress) reps = orbit_representatives(g, cell_type(g, cell_dim));
  for (Dart d : reps)
    if (!g.alive(d)) throw Error(ErrorCode::Usage, "no such dart", "dart " + std::to_string(d));
  // 1. Query every cell (§6.3). A replacement relinks only its own cell's darts (and adds new
  // ones), so the other cells' boundaries are the same before and after it: every cell is looked
  // up in the input map, and a match is kept as its pattern and its boundary darts in the order of
  // the pattern's template (the isomorphism f, replacement_template.hpp).
  struct Match {
    uint32_t pattern;
    size_t targets;  // offset of the cell's boundary darts in `targets`
    bool shared;     // a face of a 3-G-map with two half-faces
  };
  std::vector<Match> matches;
  std::vector<Dart> targets;
  size_t added = 0;
  BoundaryGraph c;
  std::vector<uint32_t> order;
  Word key;
  // local[x]: x's index in its cell's boundary graph, UINT32_MAX for the darts of cells not met
  // yet, kOtherHalf for the second half-face of a face of a 3-G-map (cell_boundary).
  constexpr uint32_t kOtherHalf = UINT32_MAX - 1;
  thread_local std::vector<uint32_t> local;
  if (local.size() < g.capacity()) local.resize(g.capacity(), UINT32_MAX);  // all UINT32_MAX between calls
  std::vector<Dart> met;  // the darts to reset when cells are listed (the sweep resets them all)
  struct Reset {
    std::vector<uint32_t>& local;
    const std::vector<Dart>& met;
    Dart capacity;
    bool all;
    ~Reset() {
      if (all) std::fill(local.begin(), local.begin() + capacity, UINT32_MAX);
      else
        for (Dart x : met) local[x] = UINT32_MAX;
    }
  } reset{local, met, g.capacity(), !(only || progress)};
  auto examine = [&](Dart rep) {
    if (progress && r.cells % 4096 == 0) progress(r.cells, reps.size());
    ++r.cells;
    cell_boundary(g, cell_dim, rep, target.flag, positive, local, c);
    if (n > cell_dim)
      for (Dart x : c.dart) {
        const Dart y = g.alpha(cell_dim + 1, x);
        if (local[y] == UINT32_MAX) local[y] = kOtherHalf;
        if (!reset.all) met.push_back(y);
      }
    if (!reset.all) met.insert(met.end(), c.dart.begin(), c.dart.end());
    // The word from the cell's first start dart, looked up (pattern_store.hpp).
    const uint32_t start = first_start_dart(c, store.mode());
    StoreMatch match;
    if (start != UINT32_MAX) {
      key.assign(1, static_cast<uint32_t>(cell_dim));
      boundary_word(c, start, key, order);
      match = store.match_word(key, start);
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
        throw Error(ErrorCode::Usage, "the duplicate selector chose pattern " + std::to_string(choice) + " of " +
                                          std::to_string(hits->size()),
                    "dart " + std::to_string(rep));
    }
    const uint32_t pattern = static_cast<uint32_t>((*hits)[choice].pattern);
    const bool shared = n > cell_dim && !g.is_free(cell_dim + 1, rep);
    matches.push_back({pattern, targets.size(), shared});
    for (uint32_t k : (*match.ranks)[choice]) targets.push_back(c.dart[order[k]]);
    added += size_t(store.replacement(pattern).interior) * (shared ? 2 : 1);
  };
  if (only || progress) {
    for (Dart rep : reps) {
      if (local[rep] != UINT32_MAX) throw Error(ErrorCode::Usage, "a cell is listed twice", "dart " + std::to_string(rep));
      examine(rep);
    }
  } else {
    g.for_each_dart([&](Dart d) {
      if (local[d] == UINT32_MAX) examine(d);
    });
  }
  // 2. Room for every copy at once: the link, flag and position arrays grow once.
  Dart next = g.add_darts(added);
  target.resize_flags();
  // 3. The replacements, in the order of the cells.
  for (const Match& m : matches) {
    next += static_cast<Dart>(replace_cell(target, store.replacement(m.pattern), &targets[m.targets], next, m.shared));
    if (after_each) after_each();
    ++r.matched[m.pattern];
  }
  r.darts_added = added;
  if (progress) progress(r.cells, reps.size());
  return r;
}

size_t replacement_room(const Map& g, const PatternStore& store, int cell_dim) {
  size_t most = 0;
  for (const Pattern& p : store.patterns())
    if (p.cell_dim == cell_dim) most = std::max(most, p.interior_darts.size());
  if (most == 0) return 0;
  const int n = g.dimension();
  size_t halves = 0;
  visit_all_orbits(
      g, cell_type(g, cell_dim).mask(), [&](Dart d) { halves += n > cell_dim && !g.is_free(cell_dim + 1, d) ? 2 : 1; },
      [](Dart) {});
  return halves * most;
}

}  // namespace gmr::replace
