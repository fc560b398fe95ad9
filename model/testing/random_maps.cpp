#include "model/testing/random_maps.hpp"

#include <limits>
#include <set>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/sew.hpp"

namespace gmr::testing {

uint64_t uniform(Rng& rng, uint64_t lo, uint64_t hi) {
  if (lo > hi) throw Error(ErrorCode::Usage, "uniform: empty range");
  const uint64_t span = hi - lo;
  if (span == std::numeric_limits<uint64_t>::max()) return rng();
  const uint64_t range = span + 1;
  // Largest multiple of `range` that fits: reject the top partial block (no modulo bias).
  const uint64_t limit =
      std::numeric_limits<uint64_t>::max() - std::numeric_limits<uint64_t>::max() % range;
  uint64_t x;
  do x = rng();
  while (x >= limit);
  return lo + x % range;
}

bool chance(Rng& rng, unsigned percent) { return uniform(rng, 0, 99) < percent; }

std::vector<Dart> random_permutation(Rng& rng, size_t n) {
  std::vector<Dart> p(n);
  for (size_t k = 0; k < n; ++k) p[k] = static_cast<Dart>(k);
  for (size_t k = n; k > 1; --k) std::swap(p[k - 1], p[uniform(rng, 0, k - 1)]);
  return p;
}

namespace {

size_t pick(Rng& rng, size_t n) { return static_cast<size_t>(uniform(rng, 0, n - 1)); }

size_t draw(Rng& rng, size_t lo, size_t hi, const char* what) {
  if (lo > hi) throw Error(ErrorCode::Usage, std::string(what) + ": min > max");
  return static_cast<size_t>(uniform(rng, lo, hi));
}

// Appends a copy of `piece` (same dimension and kind, no deleted darts) to g; returns the index
// of its first dart in g.
Dart append(Map& g, const Map& piece) {
  const Dart base = g.add_darts(piece.capacity());
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
    for (Dart d = 0; d < piece.capacity(); ++d) g.set_alpha(i, base + d, base + piece.alpha(i, d));
  return base;
}

std::vector<Dart> free_in(const Map& g, int i) {
  std::vector<Dart> out;
  g.for_each_dart([&](Dart d) {
    if (g.is_free(i, d)) out.push_back(d);
  });
  return out;
}

// All (dimension, dart) with the dart not free in that dimension, each link once (d < partner).
std::vector<std::pair<int, Dart>> sewn_links(const Map& g) {
  std::vector<std::pair<int, Dart>> out;
  for (int i = 0; i <= g.dimension(); ++i)
    g.for_each_dart([&](Dart d) {
      if (g.alpha(i, d) > d) out.emplace_back(i, d);
    });
  return out;
}

void require_gmap(const Map& g, const char* what) {
  if (g.is_omap())
    throw Error(ErrorCode::Usage, std::string(what) + " expects a G-map, not an O-map");
}

}  // namespace

// --- generators ----------------------------------------------------------------------------

Map random_glued_polygons(Rng& rng, const GluedPolygonsOptions& opt) {
  if (opt.n < 2) throw Error(ErrorCode::Range, "glued polygons need a G-map of dimension >= 2");
  if (opt.min_sides < 1) throw Error(ErrorCode::Range, "a polygon needs at least one side");
  Map g(opt.n);
  const size_t faces = draw(rng, opt.min_faces, opt.max_faces, "faces");
  for (size_t f = 0; f < faces; ++f) {
    const size_t k = draw(rng, opt.min_sides, opt.max_sides, "sides");
    const Dart base = append(g, make_polygon(k, opt.n));
    if (!opt.connected || f == 0) continue;
    // Spanning tree: glue one edge of the new polygon to a free edge of the earlier ones.
    std::vector<Dart> earlier;
    for (Dart d = 0; d < base; ++d)
      if (g.is_free(2, d)) earlier.push_back(d);
    if (earlier.empty()) continue;  // only possible with 1-gons: starts a new component
    const Dart mine = base + static_cast<Dart>(pick(rng, 2 * k));
    const Dart theirs = earlier[pick(rng, earlier.size())];
    sew(g, 2, theirs, mine);  // <0>-orbits of two free edge sides: always sewable
  }
  const size_t extra = draw(rng, 0, opt.max_extra_sews, "extra sews");
  for (size_t s = 0; s < extra; ++s) {
    const std::vector<Dart> fr = free_in(g, 2);
    if (fr.size() < 2) break;
    const Dart a = fr[pick(rng, fr.size())], b = fr[pick(rng, fr.size())];
    if (is_sewable(g, 2, a, b)) sew(g, 2, a, b);
  }
  return g;
}

std::vector<Voxel> random_voxels(Rng& rng, size_t count) {
  static constexpr int kDir[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  std::vector<Voxel> vox;
  if (count == 0) return vox;
  std::set<Voxel> in;
  vox.push_back({0, 0, 0});
  in.insert(vox.back());
  while (vox.size() < count) {
    const Voxel& v = vox[pick(rng, vox.size())];
    const auto& dir = kDir[pick(rng, 6)];
    const Voxel w{v[0] + dir[0], v[1] + dir[1], v[2] + dir[2]};
    if (in.insert(w).second) vox.push_back(w);
  }
  return vox;
}

Map random_polycube(Rng& rng, const PolycubeOptions& opt) {
  const size_t count = draw(rng, opt.min_voxels, opt.max_voxels, "voxels");
  if (count == 0) return Map(3);
  return make_polycube(random_voxels(rng, count));
}

Map random_sewn_cells(Rng& rng, const SewSequenceOptions& opt) {
  const int n = opt.n;
  Map g(n);
  const size_t cells = draw(rng, opt.min_cells, opt.max_cells, "cells");
  for (size_t c = 0; c < cells; ++c) {
    const size_t kinds = n >= 2 ? 5 : n >= 1 ? 3 : 2;
    switch (pick(rng, kinds)) {
      case 0:
        g.add_darts(1);
        break;
      case 1:
        append(g, make_free_edge(n));
        break;
      case 2:
        append(g, make_polygon(draw(rng, 1, 5, "sides"), n));
        break;
      case 3:
        append(g, pick(rng, 2) ? make_tetrahedron(n) : make_square_pyramid(n));
        break;
      default:
        append(g, make_cube(n));
        break;
    }
  }
  for (size_t step = 0; step < opt.steps; ++step) {
    if (chance(rng, opt.unsew_percent)) {
      const auto links = sewn_links(g);
      if (!links.empty()) {
        const auto [i, d] = links[pick(rng, links.size())];
        unsew(g, i, d);
        continue;
      }
    }
    const int i = static_cast<int>(uniform(rng, 0, static_cast<uint64_t>(n)));
    const std::vector<Dart> fr = free_in(g, i);
    if (fr.size() < 2) continue;
    for (size_t t = 0; t < opt.tries; ++t) {
      const Dart a = fr[pick(rng, fr.size())], b = fr[pick(rng, fr.size())];
      if (is_sewable(g, i, a, b)) {
        sew(g, i, a, b);
        break;
      }
    }
  }
  return g;
}

const char* to_string(Generator g) {
  switch (g) {
    case Generator::GluedPolygons:
      return "glued-polygons";
    case Generator::Polycube:
      return "polycube";
    case Generator::SewSequence:
      return "sew-sequence";
  }
  return "?";
}

std::vector<Generator> generators_for(int n) {
  std::vector<Generator> out;
  if (n >= 2) out.push_back(Generator::GluedPolygons);
  if (n == 3) out.push_back(Generator::Polycube);
  if (n >= 0) out.push_back(Generator::SewSequence);
  return out;
}

Map random_map(Rng& rng, Generator gen, int n) {
  switch (gen) {
    case Generator::GluedPolygons: {
      GluedPolygonsOptions o;
      o.n = n;
      return random_glued_polygons(rng, o);
    }
    case Generator::Polycube:
      if (n != 3) throw Error(ErrorCode::Range, "polycubes are 3-G-maps");
      return random_polycube(rng);
    case Generator::SewSequence: {
      SewSequenceOptions o;
      o.n = n;
      return random_sewn_cells(rng, o);
    }
  }
  throw Error(ErrorCode::Usage, "unknown generator");
}

Map random_permutation_omap(Rng& rng, const PermutationOMapOptions& opt) {
  const size_t k =
      draw(rng, std::max<size_t>(opt.min_darts, 1), opt.max_darts, "random_permutation_omap");
  Map o(2, MapKind::OMap);
  o.add_darts(k);
  const std::vector<Dart> beta1 = random_permutation(rng, k);
  for (Dart d = 0; d < k; ++d) o.set_alpha(1, d, beta1[d]);
  // beta_2: pair up a random order of the darts, leaving some as loops.
  const std::vector<Dart> order = random_permutation(rng, k);
  for (size_t p = 0; p < k; ++p) {
    const Dart d = order[p];
    if (o.alpha(2, d) != d) continue;  // already paired
    if (chance(rng, opt.loop_percent) || p + 1 == k) continue;
    size_t q = p + 1;
    while (q < k && o.alpha(2, order[q]) != order[q]) ++q;
    if (q == k) continue;
    o.set_alpha(2, d, order[q]);
    o.set_alpha(2, order[q], d);
  }
  return o;
}

Map double_along_boundary(const Map& g) {
  require_gmap(g, "double_along_boundary");
  Map out(g.dimension());
  std::vector<Dart> a(g.capacity(), kNoDart), b(g.capacity(), kNoDart);
  g.for_each_dart([&](Dart d) { a[d] = out.add_dart(); });
  g.for_each_dart([&](Dart d) { b[d] = out.add_dart(); });
  const int n = g.dimension();
  g.for_each_dart([&](Dart d) {
    for (int i = 0; i <= n; ++i) {
      if (i == n && g.alpha(i, d) == d) {
        out.set_alpha(i, a[d], b[d]);
        out.set_alpha(i, b[d], a[d]);
        continue;
      }
      out.set_alpha(i, a[d], a[g.alpha(i, d)]);
      out.set_alpha(i, b[d], b[g.alpha(i, d)]);
    }
  });
  return out;
}

Map oriented_components(const Map& g) {
  require_gmap(g, "oriented_components");
  Map out(g.dimension(), MapKind::OMap);
  std::vector<bool> seen(g.capacity(), false);
  const OrbitType all = OrbitType::range(0, g.dimension());
  g.for_each_dart([&](Dart d) {
    if (seen[d]) return;
    for (Dart e : orbit(g, all, d)) seen[e] = true;
    try {
      append(out, orient(g, d, true));
    } catch (const Error&) {
      // not orientable, or an open polygon: skipped
    }
  });
  return out;
}

// --- edits ---------------------------------------------------------------------------------

Map permute_darts(const Map& g, const std::vector<Dart>& perm) {
  const Dart cap = g.capacity();
  if (perm.size() != cap)
    throw Error(ErrorCode::Usage, "permute_darts: permutation of size " +
                                      std::to_string(perm.size()) + " for a map of capacity " +
                                      std::to_string(cap));
  std::vector<bool> hit(cap, false);
  for (Dart d = 0; d < cap; ++d) {
    if (perm[d] >= cap || hit[perm[d]])
      throw Error(ErrorCode::Usage,
                  "permute_darts: not a permutation of 0.." + std::to_string(cap) + "-1",
                  "index " + std::to_string(d));
    hit[perm[d]] = true;
  }
  Map h(g.dimension(), g.kind());
  h.add_darts(cap);
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
    g.for_each_dart([&](Dart d) {
      const Dart e = g.alpha(i, d);
      // A dangling link (invalid input) keeps its out-of-range target.
      h.set_alpha(i, perm[d], e < cap ? perm[e] : e);
    });
  for (Dart d = 0; d < cap; ++d)
    if (!g.alive(d)) h.remove_dart(perm[d]);
  return h;
}

std::string Mutation::str() const {
  const char* k = kind == Kind::Unsew   ? "unsew"
                  : kind == Kind::Sew   ? "sew"
                  : kind == Kind::Resew ? "resew"
                                        : "none";
  if (kind == Kind::None) return k;
  return std::string(k) + "_" + std::to_string(dim) + "(" + std::to_string(dart) + ", " +
         std::to_string(partner) + ")";
}

Mutation mutate_one_link(Map& g, Rng& rng) {
  require_gmap(g, "mutate_one_link");
  Mutation m;
  const auto links = sewn_links(g);
  if (!links.empty()) {
    const auto [i, d] = links[pick(rng, links.size())];
    m = {Mutation::Kind::Unsew, i, d, g.alpha(i, d)};
    unsew(g, i, d);
    return m;
  }
  if (g.size() < 2) return m;
  // Every dart is free everywhere: every <I>-orbit is a single dart, so any two distinct darts
  // are i-sewable for every i.
  const std::vector<Dart> ds = g.darts();
  const int i = static_cast<int>(uniform(rng, 0, static_cast<uint64_t>(g.dimension())));
  const size_t a = pick(rng, ds.size());
  size_t b = pick(rng, ds.size() - 1);
  if (b >= a) ++b;
  sew(g, i, ds[a], ds[b]);
  return {Mutation::Kind::Sew, i, ds[a], ds[b]};
}

Mutation resew_one_link(Map& g, Rng& rng, size_t tries) {
  require_gmap(g, "resew_one_link");
  const auto links = sewn_links(g);
  if (links.empty()) return {};
  const auto [i, d] = links[pick(rng, links.size())];
  const Dart e = g.alpha(i, d);
  unsew(g, i, d);
  const std::vector<Dart> fr = free_in(g, i);
  for (size_t t = 0; t < tries; ++t) {
    const Dart x = fr[pick(rng, fr.size())];
    if (x == e || x == d) continue;
    if (is_sewable(g, i, d, x)) {
      sew(g, i, d, x);
      return {Mutation::Kind::Resew, i, d, x};
    }
  }
  // The original pairing is the orbit isomorphism from (d, e), which Algorithm 5 rebuilds.
  sew(g, i, d, e);
  return {};
}

}  // namespace gmr::testing
