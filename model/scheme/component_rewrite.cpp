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
// next calls, buffer_pool.hpp). darts and O's links are sized once per call for the live darts (no
// component is larger); a component uses their first size() entries. O's links are the link arrays
// of a map of those darts (ComponentInstance::orbit_map): the label covers every dimension of the
// map (rewrites_whole_components), so position p's array is the map's t[p]-link array.
struct Workspace {
  explicit Workspace(int dimension) : orbit_map(dimension) {}
  ScratchTable<uint32_t> index_pool;  // per dart of the map before the call: its b, or kNone
  ScratchTable<Dart> darts_pool;      // O.darts of the current component
  Map orbit_map;                      // O's links: nb(b, p) is orbit_map's t[p]-link of b
  std::vector<uint32_t>& index = *index_pool;
  std::vector<Dart>& darts = *darts_pool;
};

// Phase 1: the component of `hook` in the BFS order of orbit_graph, with O's links; returns its
// size. The walk is bound by memory latency (a dart's links and index entries are far from the
// previous dart's), so the links of the dart kAhead places further in the queue, and the index
// entries of the darts they lead to kAhead / 2 places further, are prefetched: the order and the
// result are the plain BFS's. Arity 0: the orbit type's size, read at run time.
template <size_t Arity>
size_t component_orbit(const Map& g, const OrbitType& t, Dart hook, Workspace& w) {
  constexpr uint32_t kNone = ComponentInstance::kNone;
  constexpr size_t kAhead = 32;
  const size_t arity = Arity > 0 ? Arity : t.size();
  const Dart* link[kMaxDim];
  for (size_t p = 0; p < arity; ++p) link[p] = g.links(t[p]).data();
  uint32_t* index = w.index.data();
  Dart* darts = w.darts.data();
  uint32_t* nb[kMaxDim];
  for (size_t p = 0; p < arity; ++p) nb[p] = w.orbit_map.link_data(t[p]);
  size_t n = 1;
  darts[0] = hook;
  index[hook] = 0;
  for (size_t k = 0; k < n; ++k) {
    if (k + kAhead < n)
      for (size_t p = 0; p < arity; ++p) __builtin_prefetch(link[p] + darts[k + kAhead]);
    if (k + kAhead / 2 < n)
      for (size_t p = 0; p < arity; ++p)
        __builtin_prefetch(index + link[p][darts[k + kAhead / 2]], 1);
    const Dart x = darts[k];
    for (size_t p = 0; p < arity; ++p) {
      const Dart y = link[p][x];
      uint32_t b = index[y];
      if (b == kNone) {
        b = static_cast<uint32_t>(n);
        index[y] = b;
        darts[n++] = y;
      }
      nb[p][k] = b;
    }
  }
  return n;
}

size_t component_orbit(const Map& g, const OrbitType& t, Dart hook, Workspace& w) {
  switch (t.size()) {  // the map's dimension + 1 (rewrites_whole_components): unrolled for surfaces
    case 2:
      return component_orbit<2>(g, t, hook, w);
    case 3:
      return component_orbit<3>(g, t, hook, w);
    case 4:
      return component_orbit<4>(g, t, hook, w);
    default:
      return component_orbit<0>(g, t, hook, w);
  }
}

// Where the j-link of the darts of an added R node comes from (I_S: each dimension once per node).
struct AddedLink {
  enum Kind : uint8_t { Implicit, ToAdded, ToPreserved, Free } kind = Free;
  uint32_t position = 0;  // Implicit: the label position p with label[p] = j
  uint32_t rank = 0;      // ToAdded: the added rank of the arc's other node
};

// Per added rank r and dimension j (index r * (n + 1) + j), from R's labels and explicit arcs.
std::vector<AddedLink> added_links(const SchemeEngine& e, int n) {
  const RuleScheme& s = e.scheme();
  const auto dims = static_cast<size_t>(n) + 1;
  std::vector<AddedLink> out(e.added_count() * dims);
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    const uint32_t r = e.added_rank(v);
    if (r == SchemeEngine::kAdded) continue;
    const OrbitType& label = s.right.nodes[v].label;
    for (size_t p = 0; p < label.size(); ++p)
      if (label[p] != OrbitType::kHole)
        out[r * dims + label[p]] = {AddedLink::Implicit, static_cast<uint32_t>(p), 0};
  }
  for (const auto& a : s.right.arcs)
    for (const auto& [v, w] : {std::pair{a.a, a.b}, std::pair{a.b, a.a}}) {
      const uint32_t r = e.added_rank(v), rw = e.added_rank(w);
      if (r == SchemeEngine::kAdded) continue;
      out[r * dims + a.dim] = rw == SchemeEngine::kAdded ? AddedLink{AddedLink::ToPreserved, 0, 0}
                                                         : AddedLink{AddedLink::ToAdded, 0, rw};
    }
  return out;
}

// Phases 5 and 6 for the added nodes: their darts T[v][b] = base + rank(v) · s + b appended to the
// map with their links (each written once, by I_S): implicit arcs follow O's links inside the
// node's block, explicit arcs lead to the same b in the other node's block or to O.darts[b].
Dart add_rewritten_darts(Map& g, const SchemeEngine& e, const ComponentInstance& c,
                         const std::vector<AddedLink>& links) {
  const size_t sz = c.size();
  const auto dims = static_cast<size_t>(g.dimension()) + 1;
  const Dart* darts = c.darts.data();
  return g.add_linked_darts(e.added_count() * sz, [&](int j, Dart base, LinkAppender& out) {
    for (size_t r = 0; r < e.added_count(); ++r) {
      const Dart first = base + static_cast<Dart>(r * sz);
      const AddedLink& l = links[r * dims + static_cast<size_t>(j)];
      switch (l.kind) {
        case AddedLink::Implicit: {
          const uint32_t* from = c.nb[l.position];
          out.append(sz, [first, from](size_t b) { return first + from[b]; });
          break;
        }
        case AddedLink::ToAdded: {
          const Dart other = base + static_cast<Dart>(l.rank * sz);
          out.append(sz, [other](size_t b) { return other + static_cast<Dart>(b); });
          break;
        }
        case AddedLink::ToPreserved:
          out.append(sz, [darts](size_t b) { return darts[b]; });
          break;
        case AddedLink::Free:
          out.append(sz, [first](size_t b) { return first + static_cast<Dart>(b); });
          break;
      }
    }
  });
}

// Phase 6 for the preserved node (the hook's): its implicit arcs whose relabeling changes the
// dimension, and its ends of explicit arcs. An implicit arc at position p of dimension t[p] is the
// link the dart already has — T[v][b] -t[p]- T[v][nb(b, p)] with T[v][b] = O.darts[b] — and is not
// written.
void write_preserved_links(Map& g, const SchemeEngine& e, const ComponentInstance& c,
                           const OrbitType& t) {
  const RuleScheme& s = e.scheme();
  const size_t sz = c.size();
  const Dart* darts = c.darts.data();
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    if (e.added_rank(v) != SchemeEngine::kAdded) continue;
    const OrbitType& label = s.right.nodes[v].label;
    for (size_t p = 0; p < label.size(); ++p) {
      const int j = label[p];
      if (j == OrbitType::kHole || j == t[p]) continue;
      Dart* lj = g.link_data(j);
      const uint32_t* const nb = c.nb[p];
      for (uint32_t b = 0; b < sz; ++b) lj[darts[b]] = darts[nb[b]];
    }
  }
  for (const auto& a : s.right.arcs)
    for (const auto& [v, w] : {std::pair{a.a, a.b}, std::pair{a.b, a.a}}) {
      if (e.added_rank(v) != SchemeEngine::kAdded) continue;
      Dart* l = g.link_data(a.dim);
      const uint32_t rw = e.added_rank(w);
      if (rw == SchemeEngine::kAdded) {  // a loop on the preserved node
        c.for_each_dart([&](Dart x, uint32_t) { l[x] = x; });
      } else {
        const Dart other = c.comatch(w, 0);
        c.for_each_dart([&](Dart x, uint32_t b) { l[x] = other + b; });
      }
    }
}

}  // namespace

namespace detail {

EverywhereApplication apply_by_components(const SchemeEngine& engine, Map& g, bool keep_tables,
                                          ComponentObserver* observer) {
  if (!rewrites_whole_components(engine, g))
    throw Error(ErrorCode::Usage, "the scheme does not rewrite whole components of this map",
                "scheme " + engine.scheme().name);
  const RuleScheme& s = engine.scheme();
  const OrbitType& t = s.left.nodes[engine.hook_nodes()[0]].label;
  const size_t nr = s.right.size();
  EverywhereApplication out;
  Workspace w(g.dimension());
  const Dart cap0 = g.capacity();
  w.index_pool.reserve(cap0);
  w.index.assign(cap0, ComponentInstance::kNone);
  const std::vector<AddedLink> links = added_links(engine, g.dimension());
  const size_t live = g.size();  // no component is larger; every live dart is rewritten
  g.reserve(g.capacity() + engine.added_count() * live);  // the links grow once
  w.darts_pool.resize_for_overwrite(live);  // a component writes its entries before reading them
  w.orbit_map.resize_for_overwrite(live);
  size_t rewritten = 0;  // live darts of the components met so far: all met, no more hooks
  for (Dart d = 0; d < cap0 && rewritten < live; ++d) {
    if (!g.alive(d) || w.index[d] != ComponentInstance::kNone) continue;  // dead, or used
    const size_t sz = component_orbit(g, t, d, w);                        // 1
    rewritten += sz;
    const std::span<const Dart> orbit(w.darts.data(), sz);
    ComponentInstance c{&engine,  orbit,        {},         t.size(),
                        &w.index, g.capacity(), sz == live, &w.orbit_map};
    for (size_t p = 0; p < t.size(); ++p) c.nb[p] = w.orbit_map.link_data(t[p]);
    if (observer) observer->before_rewrite(g, c);
    if (engine.added_count() > 0) c.base = add_rewritten_darts(g, engine, c, links);  // 5, 6
    write_preserved_links(g, engine, c, t);                                           // 6
    if (!engine.deleted_nodes()
             .empty()) {  // 7: the hook, L's only node, is deleted: its darts are O's
      for (const Dart x : orbit) {
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
      app.orbit.assign(orbit.begin(), orbit.end());
      app.match = app.orbit;
      app.comatch.reserve(nr * sz);
      for (uint32_t v = 0; v < nr; ++v)
        for (uint32_t b = 0; b < sz; ++b) app.comatch.push_back(c.comatch(v, b));
    }
    out.hooks.push_back(d);
    out.applications.push_back(std::move(app));
  }
  return out;
}

}  // namespace detail

}  // namespace gmr::scheme
