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
                                 const DuplicateSelector& select, const std::vector<Dart>* only) {
  Map& g = target.map;
  const int n = g.dimension();
  if (g.is_omap()) throw Error(ErrorCode::InvalidMap, "query-replace works on G-maps");
  if (cell_dim != 2 && cell_dim != 3) throw Error(ErrorCode::Usage, "cells are faces (2) or volumes (3)", "--cells");
  if (n != cell_dim && n != cell_dim + 1)
    throw Error(ErrorCode::InvalidMap, std::to_string(cell_dim) + "-cells are replaced in " + std::to_string(cell_dim) +
                                           "- or " + std::to_string(cell_dim + 1) + "-G-maps, not in a " +
                                           std::to_string(n) + "-G-map");
  const ValidityReport v = check_validity(g, 1);
  if (!v.ok()) throw Error(ErrorCode::InvalidMap, "the map is not valid: " + v.violations.front().describe());
  target.resize_flags();
  QueryReplaceReport r;
  r.mode = store.mode();
  r.cell_dim = cell_dim;
  r.matched.assign(store.patterns().size(), 0);
  std::vector<uint8_t> positive;
  if (store.mode() == Mode::Oriented) positive = orientation_classes(g);
  // A face of a 3-G-map is a <0,1,3>-orbit; a volume a <0,1,2>-orbit; faces of 2-G-maps <0,1>.
  const OrbitType cells = cell_type(g, cell_dim);
  const std::vector<Dart> reps = only ? *only : orbit_representatives(g, cells);
  for (Dart d : reps)
    if (!g.alive(d)) throw Error(ErrorCode::Usage, "no such dart", "dart " + std::to_string(d));
  r.cells = reps.size();
  // Room for the copies (at most the largest interior per cell, twice for shared faces), so that
  // the link, flag and position arrays grow once.
  size_t most = 0;
  for (const Pattern& p : store.patterns())
    if (p.cell_dim == cell_dim) most = std::max(most, p.interior_darts.size());
  const size_t room = g.capacity() + reps.size() * most * (n > cell_dim ? 2 : 1);
  g.reserve(room);
  target.flag.reserve(room);
  if (target.positioned()) target.position.reserve(room);
  // Per pattern, its darts in the label order of its minimal start (computed on first use).
  std::vector<std::vector<uint32_t>> pattern_order(store.patterns().size());
  std::vector<Dart> f;
  size_t done = 0;
  for (Dart rep : reps) {
    if (progress && done % 4096 == 0) progress(done, reps.size());
    ++done;
    const BoundaryGraph c = cell_boundary(g, cell_dim, rep, target.flag, positive);
    const StoreMatch match = store.match(c, cell_dim);
    const std::vector<StoreEntry>* hits = match.hits;
    if (!hits) {
      r.unmatched.push_back(rep);
      continue;
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
    const StoreEntry& pe = (*hits)[choice];
    const Pattern& p = store.patterns()[pe.pattern];
    const std::vector<uint32_t> oc = boundary_labeling(c, match.start);
    std::vector<uint32_t>& op = pattern_order[pe.pattern];
    if (op.empty()) op = boundary_labeling(p.boundary, pe.start);
    f.assign(p.map.map.capacity(), kNoDart);
    for (size_t k = 0; k < op.size(); ++k) f[p.boundary.dart[op[k]]] = c.dart[oc[k]];
    r.darts_added += replace_cell(target, p, f);
    if (after_each) after_each();
    ++r.matched[pe.pattern];  // the next cells' darts are not touched: no new darts to orient
  }
  if (progress) progress(reps.size(), reps.size());
  return r;
}

}  // namespace gmr::replace
