#include "model/replace/edge_split.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/core/generated_append.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"

namespace gmr::replace {

size_t split_edge(FlaggedMap& m, Dart d, unsigned k) { return split_edges(m, {d}, k); }

namespace {

// Per old dart x, the new dart next to it on its chain (kNoDart between uses): a per-thread array
// indexed by dart, reset after each use.
std::vector<Dart>& chain_heads(Dart capacity) {
  thread_local std::vector<Dart> near;
  resize_in_huge_pages(near, capacity, kNoDart);
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
      if (seen.test(e))
        throw Error(ErrorCode::Usage, "an edge is listed twice", "dart " + std::to_string(e));
      visit_orbit_marked(g, edge, e, seen.id(), stack, [&](Dart x) { darts.push_back(x); });
    }
    for (Dart x : darts) seen.unmark(x);
    seen.set_clean();
  }
  return split_pairs(m, darts, k);
}

namespace {

size_t split_every_dart(FlaggedMap& m, unsigned k);

}  // namespace

size_t split_all_edges(FlaggedMap& m, unsigned k) {
  if (k == 0) throw Error(ErrorCode::Usage, "an edge is split into at least 1 edge");
  if (k == 1) return 0;
  // Every dart pair (x, alpha_0 x) is split, no edge traversal: without holes, each dart's half of
  // its chain numbered from the dart itself; else the pairs in dart order.
  if (!m.map.has_holes()) return split_every_dart(m, k);
  return split_pairs(m, m.map.darts(), k);
}

namespace {

// The chains' links, flags and positions, appended (each array written once, in dart order). Chain
// p runs from pairs[p] = x to y = alpha_0 x: its s-th dart (counted from x) is first + p len + s,
// alpha_0 and alpha_1 alternate along it, and for j >= 2 alpha_j sends it to the s-th dart counted
// from z = alpha_j x on z's chain (near[z] + s or near[z] - s as that chain runs from z or to z),
// to itself when x is j-free. L: len when known at compile time (2: a split in 2), else 0.
template <Dart L>
void append_chains(FlaggedMap& m, const std::vector<Dart>& pairs, const Dart* near, Dart len_,
                   unsigned k) {
  Map& g = m.map;
  const Dart len = L ? L : len_;
  const Dart added = static_cast<Dart>(pairs.size()) * len;
  const Dart first = g.capacity();
  auto upwards = [&](Dart z) { return (near[z] - first) % len == 0; };
  g.add_linked_darts(added, [&](int d, Dart, LinkAppender& out) {
    const Dart* link = g.links(d).data();  // room reserved: the old links stay in place
    const Dart* link0 = g.links(0).data();
    if (d == 0)
      return out.append(added, [&](size_t c) {
        const Dart p = static_cast<Dart>(c / len), s = static_cast<Dart>(c % len),
                   self = first + static_cast<Dart>(c);
        if (s == 0) return pairs[p];
        if (s % 2 == 0) return self - 1;
        return s == len - 1 ? link0[pairs[p]] : self + 1;
      });
    if (d == 1)
      return out.append(added, [&](size_t c) {
        const Dart self = first + static_cast<Dart>(c);
        return (c % len) % 2 == 0 ? self + 1 : self - 1;
      });
    out.append(added, [&](size_t c) {
      const Dart p = static_cast<Dart>(c / len), s = static_cast<Dart>(c % len);
      const Dart x = pairs[p], z = link[x];
      if (z == x) return first + static_cast<Dart>(c);
      return upwards(z) ? near[z] + s : near[z] - s;
    });
  });
  append_generated(m.flag, added, [](size_t) { return uint32_t(0); });
  if (m.positioned()) {
    const Vec3* pos = m.position.data();  // room reserved: the old positions stay in place
    const Dart* link0 = g.links(0).data();
    append_generated(m.position, added, [&](size_t c) {
      // the vertex t (1..k-1) at t/k from x's vertex
      const Dart p = static_cast<Dart>(c / len), s = static_cast<Dart>(c % len);
      const Vec3 a = pos[pairs[p]], b = pos[link0[pairs[p]]];
      const double t = double(s / 2 + 1) / k;
      return Vec3{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    });
  }
  // The old darts' alpha_0: the end of their chain.
  Dart* link0 = g.link_data(0);
  for (Dart x : pairs) {
    const Dart y = link0[x];
    link0[x] = near[x];
    link0[y] = near[y];
  }
}

// Room for `total` darts in the links, flags and positions before the new darts are written (the
// old ones are read while the new ones are appended); grown geometrically, as the arrays grow.
void make_room(FlaggedMap& m, size_t total) {
  Map& g = m.map;
  const size_t first = g.capacity();
  bool room = true;
  for (int d = 0; d <= g.dimension(); ++d) room &= g.links(d).capacity() >= total;
  if (!room) g.reserve(std::max(total, 2 * first));
  m.grow_flags(total);
}

// Every pair split on a map without holes: old dart x gets the h = k - 1 new darts
// first + h x + s, s = 0..h-1 counted from x, so the chain of (x, y = alpha_0 x) is x's darts then
// y's in reverse (its s-th dart from x is x's s-th for s < h, and y's (2h - 1 - s)-th otherwise).
// Along the chain alpha_0 and alpha_1 alternate from x (alpha_0 of the first dart is x); for j >=
// 2, alpha_j sends x's s-th dart to the s-th of z = alpha_j x (to itself when x is j-free). Every
// link is thus computed from x and its own links: no chain table. The new vertex m (1..k-1 from x)
// is placed at ((k - m) p(x) + m p(y)) / k, the same value from either end. H: h when known at
// compile time (1: a split in 2), else 0.
template <Dart H>
void append_dart_chains(FlaggedMap& m, unsigned k) {
  Map& g = m.map;
  const Dart n = g.capacity(), first = n;
  const Dart h = H ? H : static_cast<Dart>(k - 1);
  const size_t added = size_t(h) * n;
  const Dart* link0 = g.links(0).data();  // room reserved: the old links stay in place
  auto dart = [&](Dart x, Dart s) { return first + h * x + s; };
  // The s-th dart from x on the chain, s = 0..2h-1.
  auto chain = [&](Dart x, Dart s) { return s < h ? dart(x, s) : dart(link0[x], 2 * h - 1 - s); };
  g.add_linked_darts(added, [&](int d, Dart, LinkAppender& out) {
    if (d == 0)
      return out.append(added, [&](size_t c) {
        const Dart x = static_cast<Dart>(c / h), s = static_cast<Dart>(c % h);
        if (s == 0) return x;
        return s % 2 == 0 ? chain(x, s - 1) : chain(x, s + 1);
      });
    if (d == 1)
      return out.append(added, [&](size_t c) {
        const Dart x = static_cast<Dart>(c / h), s = static_cast<Dart>(c % h);
        return s % 2 == 0 ? chain(x, s + 1) : chain(x, s - 1);
      });
    const Dart* link = g.links(d).data();
    out.append(added, [&](size_t c) {
      const Dart x = static_cast<Dart>(c / h), s = static_cast<Dart>(c % h), z = link[x];
      return z == x ? first + static_cast<Dart>(c) : dart(z, s);
    });
  });
  append_generated(m.flag, added, [](size_t) { return uint32_t(0); });
  if (m.positioned()) {
    const Vec3* pos = m.position.data();  // room reserved: the old positions stay in place
    append_generated(m.position, added, [&](size_t c) {
      const Dart x = static_cast<Dart>(c / h), s = static_cast<Dart>(c % h);
      const Vec3 a = pos[x], b = pos[link0[x]];
      const double along = double(s / 2 + 1), rest = double(k) - along;
      return Vec3{(rest * a[0] + along * b[0]) / k, (rest * a[1] + along * b[1]) / k,
                  (rest * a[2] + along * b[2]) / k};
    });
  }
  // The old darts' alpha_0: the first dart of their chain.
  Dart* old0 = g.link_data(0);
  for (Dart x = 0; x < n; ++x) old0[x] = dart(x, 0);
}

size_t split_every_dart(FlaggedMap& m, unsigned k) {
  Map& g = m.map;
  const Dart n = g.capacity();
  const Dart* link0 = g.links(0).data();
  for (Dart x = 0; x < n; ++x)
    if (link0[x] == x)
      throw Error(ErrorCode::InvalidMap, "a 0-free dart has no edge to split",
                  "dart " + std::to_string(x));
  if (double(k - 1) * double(n) >= double(kNoDart - n))
    throw Error(ErrorCode::Range, "too many darts (limit " + std::to_string(kNoDart - 1) + ")",
                "split in " + std::to_string(k));
  m.resize_flags();
  make_room(m, size_t(n) * k);
  if (k == 2)
    append_dart_chains<1>(m, k);
  else
    append_dart_chains<0>(m, k);
  return size_t(n) * (k - 1);
}

// 2.-3. Splits each pair (x, alpha_0 x) of `darts` (both darts of every pair listed, each pair
// once), chains numbered in the order of the pairs' first darts.
size_t split_pairs(FlaggedMap& m, const std::vector<Dart>& darts, unsigned k) {
  Map& g = m.map;
  const Dart len = 2 * (k - 1);
  for (Dart x : darts)
    if (g.is_free(0, x))
      throw Error(ErrorCode::InvalidMap, "a 0-free dart has no edge to split",
                  "dart " + std::to_string(x));
  if (double(k - 1) * double(darts.size()) >= double(kNoDart - g.capacity()))
    throw Error(ErrorCode::Range, "too many darts (limit " + std::to_string(kNoDart - 1) + ")",
                "split in " + std::to_string(k));
  m.resize_flags();
  // 2. One chain of len new darts per pair (x, alpha_0 x), numbered from the end of the map:
  // near[x] is its end next to x, near[alpha_0 x] the other end.
  const Dart first = g.capacity();
  const size_t added = size_t(len) * (darts.size() / 2), total = size_t(first) + added;
  make_room(m, total);
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
  // 3. The chains appended, linked by alpha_j (j >= 2) as their ends are.
  if (len == 2)
    append_chains<2>(m, pairs, near.data(), len, k);
  else
    append_chains<0>(m, pairs, near.data(), len, k);
  for (Dart x : darts) near[x] = kNoDart;
  return darts.size() * (k - 1);
}

}  // namespace

}  // namespace gmr::replace
