#include "model/replace/edge_split.hpp"

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::replace {

size_t split_edge(FlaggedMap& m, Dart d, unsigned k) { return split_edges(m, {d}, k); }

namespace {

// Per old dart x, the new dart next to it on its chain (kNoDart between uses): a per-thread array
// indexed by dart, reset after each use.
std::vector<Dart>& chain_heads(Dart capacity) {
  thread_local std::vector<Dart> near;
  if (near.size() < capacity) near.resize(capacity, kNoDart);
  return near;
}

}  // namespace

namespace {

size_t split_pairs(FlaggedMap& m, const std::vector<Dart>& darts, unsigned k);

}  // namespace

size_t split_edges(FlaggedMap& m, const std::vector<Dart>& edges, unsigned k) {
  if (k == 0) throw Error(ErrorCode::Usage, "an edge is split into at least 1 edge");
  if (k == 1) return 0;
  Map& g = m.map;
  // 1. The darts of the edges, edge by edge.
  std::vector<Dart> darts;
  {
    ScopedMarker seen(g);
    std::vector<Dart> stack;
    const DimMask edge = cell_type(g, 1).mask();
    for (Dart e : edges) {
      if (!g.alive(e)) throw Error(ErrorCode::Usage, "no such dart", "dart " + std::to_string(e));
      if (seen.test(e)) throw Error(ErrorCode::Usage, "an edge is listed twice", "dart " + std::to_string(e));
      visit_orbit_marked(g, edge, e, seen.id(), stack, [&](Dart x) { darts.push_back(x); });
    }
    for (Dart x : darts) seen.unmark(x);
    seen.set_clean();
  }
  return split_pairs(m, darts, k);
}

size_t split_all_edges(FlaggedMap& m, unsigned k) {
  if (k == 0) throw Error(ErrorCode::Usage, "an edge is split into at least 1 edge");
  if (k == 1) return 0;
  // Every dart pair (x, alpha_0 x) is split: the darts in index order, no edge traversal.
  return split_pairs(m, m.map.darts(), k);
}

namespace {

// 2.-3. Splits each pair (x, alpha_0 x) of `darts` (both darts of every pair listed, each pair
// once), chains numbered in the order of the pairs' first darts.
size_t split_pairs(FlaggedMap& m, const std::vector<Dart>& darts, unsigned k) {
  Map& g = m.map;
  const Dart len = 2 * (k - 1);
  for (Dart x : darts)
    if (g.is_free(0, x)) throw Error(ErrorCode::InvalidMap, "a 0-free dart has no edge to split", "dart " + std::to_string(x));
  if (double(k - 1) * double(darts.size()) >= double(kNoDart - g.capacity()))
    throw Error(ErrorCode::Range, "too many darts (limit " + std::to_string(kNoDart - 1) + ")", "split in " + std::to_string(k));
  // 2. One chain of len new darts per pair (x, alpha_0 x), all added at once: near[x] is its end
  // next to x, near[alpha_0 x] the other end.
  const Dart first = g.add_darts(size_t(len) * (darts.size() / 2));
  m.resize_flags();
  std::vector<Dart>& near = chain_heads(first);
  std::vector<Dart> pairs;  // the x of each pair, in chain order
  pairs.reserve(darts.size() / 2);
  for (Dart x : darts) {
    if (near[x] != kNoDart) continue;
    const Dart c = first + static_cast<Dart>(pairs.size()) * len;
    near[x] = c;
    near[g.alpha(0, x)] = c + len - 1;
    pairs.push_back(x);
  }
  // The chain runs upwards from the x of its pair: the s-th dart counted from x is near[x] + s
  // there, near[x] - s from the other end.
  auto upwards = [&](Dart x) { return (near[x] - first) % len == 0; };
  for (Dart x : pairs) {
    const Dart y = g.alpha(0, x), c = near[x];
    g.link(0, x, c);
    for (Dart s = 0; s + 1 < len; ++s) g.link(s % 2 == 0 ? 1 : 0, c + s, c + s + 1);
    g.link(0, c + len - 1, y);
    if (m.positioned()) {  // vertex t (1..k-1) at t/k from x's vertex
      const Vec3 a = m.position[x], b = m.position[y];
      for (Dart s = 0; s < len; ++s) {
        const double t = double(s / 2 + 1) / k;
        m.position[c + s] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
      }
    }
  }
  // 3. alpha_j (j >= 2) links the chains as it links their ends (each side writes its direction).
  for (Dart x : darts)
    for (int j = 2; j <= g.dimension(); ++j) {
      const Dart z = g.alpha(j, x);
      if (z == x) continue;
      const Dart cx = near[x], cz = near[z];
      const bool ux = upwards(x), uz = upwards(z);
      for (Dart s = 0; s < len; ++s) g.set_alpha(j, ux ? cx + s : cx - s, uz ? cz + s : cz - s);
    }
  for (Dart x : darts) near[x] = kNoDart;
  return darts.size() * (k - 1);
}

}  // namespace

}  // namespace gmr::replace
