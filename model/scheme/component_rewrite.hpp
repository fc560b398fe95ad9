// Application at every dart of a scheme whose left-hand side is its hook alone, labelled with
// every dimension 0..n (the whole-surface subdivision schemes of tools/data/rules/): the hook
// orbit is a whole connected component, and apply_everywhere makes exactly one application per
// component, at its smallest dart, in increasing order (apply_everywhere.hpp).
//
// Every such application matches (thesis §4.3.4, the engine's phase 4): L instantiated on the
// component is the component itself (its implicit arcs are the links followed to build the orbit
// graph, its nodes the orbit's darts, pairwise distinct). So the rewrite of one component is the
// engine's phases 1 and 5–7 (scheme_engine.hpp) with nothing to check: the orbit graph O by the
// BFS of orbit_graph (Algorithm 4, same order), R node v at orbit dart b is the dart
//     comatch(v, b) = O.darts[b]                      (v preserved)
//                   = base + rank(v) · s + b          (v added, rank among the added nodes),
// implicit arcs follow O's links (T[v][b] –j– T[v][nb(b, p)]), explicit arcs stay at b, and the
// deleted darts are freed. This path does it on flat arrays shared by the components of one call
// (the dart index doubles as the "used" table, no hashing, no match table; O's links one array
// per label position, read in order by the passes after the BFS), in three passes per
// component: the BFS (with prefetching), the added nodes' darts appended with their links — one
// sequential write per dimension and node, each link written once (Map::add_linked_darts) — and
// the preserved node's changed links (its implicit arcs whose relabeling keeps the dimension are
// the links it already has, and are not rewritten). The link arrays grow once per call, to the
// final size. The result is the map
// scheme::apply gives, dart for dart (tested against it on random maps and schemes in
// model/scheme/tests/component_rewrite_test.cpp).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "model/core/map.hpp"
#include "model/scheme/apply_everywhere.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::scheme {

// One component being rewritten, as the observers see it.
struct ComponentInstance {
  static constexpr uint32_t kNone = UINT32_MAX;
  const SchemeEngine* engine = nullptr;
  std::span<const Dart> darts;  // O.darts[b] (BFS order of orbit_graph)
  // O's links, one array per label position: nb[p][b] is the orbit dart linked to b at position p.
  std::array<const uint32_t*, kMaxDim> nb = {};
  size_t arity = 0;
  const std::vector<uint32_t>* index = nullptr;  // index[x] = b for a dart x of the component
  Dart base = 0;                                 // the first added dart (valid after the rewrite)
  bool whole_map = false;                        // the component holds every live dart of the map
  // O as a map whose dart b is orbit dart b: the i-link of b < size() is nb[p][b] for the position
  // p of dimension i (the hook's label covers every dimension). Its capacity is the call's room
  // (the live darts of the map before it): equal to size() when the component is the whole map.
  const Map* orbit_map = nullptr;

  size_t size() const { return darts.size(); }
  // f(x, b) for every dart x = O.darts[b] of the component: in dart order when the component is
  // the whole map (writes to per-dart arrays are then sequential; in b order they land anywhere),
  // else in b order.
  template <class F>
  void for_each_dart(F&& f) const {
    if (whole_map) {
      const uint32_t* const ix = index->data();
      const size_t n = index->size();
      for (Dart x = 0; x < n; ++x)
        if (ix[x] != kNone) f(x, ix[x]);
    } else {
      for (uint32_t b = 0; b < darts.size(); ++b) f(darts[b], b);
    }
  }
  uint32_t neighbor(uint32_t b, size_t p) const { return nb[p][b]; }
  // The dart of the result for R node v at orbit dart b.
  Dart comatch(uint32_t v, uint32_t b) const {
    const uint32_t r = engine->added_rank(v);
    return r == SchemeEngine::kAdded ? darts[b] : base + static_cast<Dart>(r * darts.size() + b);
  }
};

// Sees each component's rewrite, like ApplicationObserver sees an application.
class ComponentObserver {
 public:
  virtual ~ComponentObserver() = default;
  virtual void before_rewrite(const Map& g, const ComponentInstance& c) = 0;
  virtual void after_rewrite(const Map& g, const ComponentInstance& c) = 0;
};

// Whether apply_everywhere(engine, g) can take this path (EverywherePath::ByComponents): one hook,
// L = the hook alone with every dimension of g in its label, no `_`, I_S(0..n) holds (the scheme
// applies), and g is a G-map of the scheme's dimension.
bool rewrites_whole_components(const SchemeEngine& engine, const Map& g);

namespace detail {
// apply_everywhere's whole-component path: the same result as its application at each dart (same
// applications, hooks, darts added and deleted; orbit, match and comatch tables with keep_tables).
// Requires rewrites_whole_components (throws Error(Usage) otherwise).
EverywhereApplication apply_by_components(const SchemeEngine& engine, Map& g, bool keep_tables,
                                          ComponentObserver* observer);
}  // namespace detail

}  // namespace gmr::scheme
