#include "model/scheme/component_rewrite.hpp"

#include "model/core/buffer_pool.hpp"
#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"

namespace gmr::scheme {

bool rewrites_whole_components(const SchemeEngine& engine, const Map& g) {
  const RuleScheme& s = engine.scheme();
  if (g.kind() != MapKind::GMap || g.dimension() != s.dimension) return false;
  if (!engine.not_combinatorial().empty()) return false;
  if (engine.hook_nodes().size() != 1 || s.left.size() != 1 || !s.left.arcs.empty()) return false;
  const OrbitType& t = s.left.nodes[engine.hook_nodes()[0]].label;
  return !t.has_hole() && t.mask() == g.dims_mask();
}

namespace {

// The flat tables of one call, reused by its components (their storage kept by the thread for its
// next calls, buffer_pool.hpp).
struct Workspace {
  Pooled<uint32_t> index_pool;  // per dart of the map before the call: its b, or kNone (not yet met)
  Pooled<Dart> darts_pool;      // O.darts of the current component
  Pooled<uint32_t> nb_pool;     // O's links
  std::vector<uint32_t>& index = *index_pool;
  std::vector<Dart>& darts = *darts_pool;
  std::vector<uint32_t>& nb = *nb_pool;
};

// Phase 1: the component of `hook` in the BFS order of orbit_graph, with O's links.
void component_orbit(const Map& g, const OrbitType& t, Dart hook, Workspace& w) {
  constexpr uint32_t kNone = ComponentInstance::kNone;
  const size_t arity = t.size();
  const Dart* link[kMaxDim];
  for (size_t p = 0; p < arity; ++p) link[p] = g.links(t[p]).data();
  uint32_t* index = w.index.data();
  w.darts.clear();
  w.nb.clear();
  w.darts.push_back(hook);
  index[hook] = 0;
  for (size_t k = 0; k < w.darts.size(); ++k) {
    const Dart x = w.darts[k];
    for (size_t p = 0; p < arity; ++p) {
      const Dart y = link[p][x];
      if (index[y] == kNone) {
        index[y] = static_cast<uint32_t>(w.darts.size());
        w.darts.push_back(y);
      }
      w.nb.push_back(index[y]);
    }
  }
}

// Phase 6: the links of R (each dart and dimension written once, by I_S).
void write_links(Map& g, const SchemeEngine& e, const ComponentInstance& c) {
  const RuleScheme& s = e.scheme();
  const size_t sz = c.size();
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    const OrbitType& label = s.right.nodes[v].label;
    const bool added = e.added_rank(v) != SchemeEngine::kAdded;
    const Dart first = added ? c.comatch(v, 0) : 0;
    for (size_t p = 0; p < label.size(); ++p) {
      if (label[p] == OrbitType::kHole) continue;
      const int j = label[p];
      if (added) {
        for (uint32_t b = 0; b < sz; ++b) g.set_alpha(j, first + b, first + c.neighbor(b, p));
      } else {
        for (uint32_t b = 0; b < sz; ++b) g.set_alpha(j, c.darts[b], c.darts[c.neighbor(b, p)]);
      }
    }
  }
  for (const auto& a : s.right.arcs)
    for (uint32_t b = 0; b < sz; ++b) {
      const Dart x = c.comatch(a.a, b), y = c.comatch(a.b, b);
      g.set_alpha(a.dim, x, y);
      g.set_alpha(a.dim, y, x);
    }
}

}  // namespace

EverywhereApplication apply_everywhere_by_components(const SchemeEngine& engine, Map& g, bool keep_tables,
                                                     ComponentObserver* observer) {
  if (!rewrites_whole_components(engine, g))
    throw Error(ErrorCode::Usage, "the scheme does not rewrite whole components of this map",
                "scheme " + engine.scheme().name);
  const RuleScheme& s = engine.scheme();
  const OrbitType& t = s.left.nodes[engine.hook_nodes()[0]].label;
  const size_t nr = s.right.size();
  EverywhereApplication out;
  Workspace w;
  const Dart cap0 = g.capacity();
  w.index_pool.reserve(cap0);
  w.index.assign(cap0, ComponentInstance::kNone);
  w.darts_pool.reserve(cap0);  // bounds; pages untouched beyond the largest component
  w.nb_pool.reserve(cap0 * t.size());
  for (Dart d = 0; d < cap0; ++d) {
    if (!g.alive(d) || w.index[d] != ComponentInstance::kNone) continue;  // dead, or used
    component_orbit(g, t, d, w);  // 1
    ComponentInstance c{&engine, w.darts, w.nb, t.size(), &w.index, g.capacity()};
    const size_t sz = c.size();
    if (observer) observer->before_rewrite(g, c);
    if (engine.added_count() > 0) c.base = g.add_darts(engine.added_count() * sz);  // 5
    write_links(g, engine, c);                                                        // 6
    if (!engine.deleted_nodes().empty()) {  // 7: the hook, L's only node, is deleted: its darts are O's
      for (uint32_t b = 0; b < sz; ++b) {
        const Dart x = w.darts[b];
        for (int i = 0; i <= g.dimension(); ++i) g.set_alpha(i, x, x);
        g.remove_dart(x);
      }
    }
    SchemeApplication app;
    app.applied = true;
    app.darts_added = engine.added_count() * sz;
    app.darts_deleted = engine.deleted_nodes().size() * sz;
    if (observer) observer->after_rewrite(g, c);
    if (keep_tables) {
      app.orbit = w.darts;
      app.match = w.darts;
      app.comatch.reserve(nr * sz);
      for (uint32_t v = 0; v < nr; ++v)
        for (uint32_t b = 0; b < sz; ++b) app.comatch.push_back(c.comatch(v, b));
    }
    out.hooks.push_back(d);
    out.applications.push_back(std::move(app));
  }
  return out;
}

}  // namespace gmr::scheme
