// The optimised traversals (visit_orbit_marked, visit_all_orbits) and check_validity against
// plain reference implementations (the straightforward code they replaced), on valid and invalid
// maps, G-maps and O-maps, with and without deleted darts: same darts in the same order, same
// violations in the same order.
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/testing/random_maps.hpp"

using namespace gmr;
using namespace gmr::testing;

namespace {

// Plain stack DFS: pop, visit, push unmarked neighbours in increasing dimension order; links to
// non-existent indices are not followed.
std::vector<Dart> ref_visit(const Map& g, DimMask mask, Dart d, std::vector<bool>& seen) {
  std::vector<Dart> out, stack{d};
  seen[d] = true;
  while (!stack.empty()) {
    const Dart v = stack.back();
    stack.pop_back();
    out.push_back(v);
    for (int i = 0; i < kMaxDim; ++i) {
      if (!(mask >> i & 1)) continue;
      const Dart w = g.alpha(i, v);
      if (w >= g.capacity() || seen[w]) continue;
      seen[w] = true;
      stack.push_back(w);
    }
  }
  return out;
}

// The validity check as first written (before the fast paths).
ValidityReport ref_validity(const Map& g, size_t limit) {
  ValidityReport r;
  auto add = [&](ConstraintViolation v) {
    if (r.violations.size() < limit)
      r.violations.push_back(std::move(v));
    else
      ++r.truncated;
  };
  const int lo = g.lowest_dim(), n = g.dimension();
  std::vector<bool> dim_ok(static_cast<size_t>(n) + 1, true);
  for (int i = lo; i <= n; ++i) {
    const auto& l = g.links(i);
    const bool invol = g.is_involutive_dim(i);
    g.for_each_dart([&](Dart d) {
      const Dart e = l[d];
      if (!g.alive(e)) {
        dim_ok[i] = false;
        add({Constraint::IncidentArcs, d, i, -1, {d, e}});
        return;
      }
      if (invol && l[e] != d) add({Constraint::NonOrientation, d, i, -1, {d, e, l[e]}});
    });
    if (!invol && dim_ok[i]) {
      std::vector<Dart> from(g.capacity(), kNoDart);
      g.for_each_dart([&](Dart d) {
        const Dart e = l[d];
        if (from[e] != kNoDart)
          add({Constraint::IncidentArcs, e, i, -1, {from[e], d}});
        else
          from[e] = d;
      });
    }
  }
  for (int i = lo; i <= n; ++i)
    for (int j = i + 2; j <= n; ++j) {
      if (!dim_ok[i] || !dim_ok[j]) continue;
      const auto& li = g.links(i);
      const auto& lj = g.links(j);
      g.for_each_dart([&](Dart d) {
        const Dart a = li[d], b = lj[a], c = li[b], e = lj[c];
        if (e != d) add({Constraint::Cycle, d, i, j, {d, a, b, c, e}});
      });
    }
  return r;
}

bool same(const ValidityReport& a, const ValidityReport& b) {
  if (a.truncated != b.truncated || a.violations.size() != b.violations.size()) return false;
  for (size_t k = 0; k < a.violations.size(); ++k) {
    const auto &x = a.violations[k], &y = b.violations[k];
    if (x.constraint != y.constraint || x.at != y.at || x.i != y.i || x.j != y.j ||
        x.path != y.path)
      return false;
  }
  return true;
}

// Every orbit type over the map's dimensions (all subsets), each traversed from every dart, and
// the all-orbits scan, against the reference.
void check_traversals(const Map& g, const std::string& what) {
  SCOPED_TRACE(what);
  const DimMask all = g.dims_mask();
  std::vector<Dart> stack;
  for (DimMask mask = 0; mask <= all; ++mask) {
    if ((mask & ~all) != 0) continue;
    // From every dart.
    g.for_each_dart([&](Dart d) {
      std::vector<bool> seen(g.capacity(), false);
      const auto expect = ref_visit(g, mask, d, seen);
      std::vector<Dart> got;
      ScopedMarker m(g);
      const size_t k =
          visit_orbit_marked(g, mask, d, m.id(), stack, [&](Dart x) { got.push_back(x); });
      ASSERT_EQ(got, expect) << "mask " << mask << " from " << d;
      ASSERT_EQ(k, got.size());
      for (Dart x : got) ASSERT_TRUE(m.test(x));
    });
    // All orbits.
    std::vector<bool> seen(g.capacity(), false);
    std::vector<Dart> expect_reps, expect_darts;
    g.for_each_dart([&](Dart d) {
      if (seen[d]) return;
      expect_reps.push_back(d);
      for (Dart x : ref_visit(g, mask, d, seen)) expect_darts.push_back(x);
    });
    std::vector<Dart> reps, darts;
    const size_t n = visit_all_orbits(
        g, mask, [&](Dart r) { reps.push_back(r); }, [&](Dart x) { darts.push_back(x); });
    ASSERT_EQ(n, reps.size());
    ASSERT_EQ(reps, expect_reps) << "mask " << mask;
    ASSERT_EQ(darts, expect_darts) << "mask " << mask;
  }
  for (size_t limit : {size_t(0), size_t(2), size_t(1000)})
    EXPECT_TRUE(same(check_validity(g, limit), ref_validity(g, limit))) << "limit " << limit;
}

// Corrupts g: `k` random one-way writes, some dangling (target >= capacity) when `dangling`.
void corrupt(Map& g, Rng& rng, int k, bool dangling) {
  const auto ds = g.darts();
  if (ds.empty()) return;
  for (int t = 0; t < k; ++t) {
    const Dart d = ds[uniform(rng, 0, ds.size() - 1)];
    const int i = static_cast<int>(
        uniform(rng, static_cast<uint64_t>(g.lowest_dim()), static_cast<uint64_t>(g.dimension())));
    const Dart x = dangling && chance(rng, 30)
                       ? g.capacity() + static_cast<Dart>(uniform(rng, 0, 5))
                       : ds[uniform(rng, 0, ds.size() - 1)];
    g.set_alpha(i, d, x);
  }
}

}  // namespace

TEST(TraversalEquivalence, ValidRandomMaps) {
  for (int n = 0; n <= 3; ++n)
    for (Generator gen : generators_for(n))
      for (uint64_t seed = 0; seed < 12; ++seed) {
        Rng rng(seed);
        check_traversals(random_map(rng, gen, n), std::string(to_string(gen)) +
                                                      " n=" + std::to_string(n) +
                                                      " seed=" + std::to_string(seed));
        if (HasFatalFailure()) return;
      }
}

TEST(TraversalEquivalence, StandardObjects) {
  check_traversals(make_torus(3, 4), "torus");
  check_traversals(make_grid(3, 2), "grid");
  check_traversals(make_stacked_cubes(), "stacked cubes");
  check_traversals(make_polygon(1), "1-gon");
  check_traversals(orient(make_cube()), "cube O-map");
  check_traversals(orient(make_torus(3, 3)), "torus O-map");
}

TEST(TraversalEquivalence, InvalidMaps) {
  for (uint64_t seed = 0; seed < 60; ++seed) {
    Rng rng(seed);
    Map g = random_map(rng, seed % 2 ? Generator::SewSequence : Generator::GluedPolygons,
                       2 + int(seed % 3 == 0));
    corrupt(g, rng, 1 + static_cast<int>(seed % 4), seed % 5 == 0);
    check_traversals(g, "corrupted seed=" + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
  for (uint64_t seed = 0; seed < 20; ++seed) {
    Rng rng(seed);
    Map o = orient(make_torus(3, 3));
    corrupt(o, rng, 2, seed % 3 == 0);
    check_traversals(o, "corrupted O-map seed=" + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
}

TEST(TraversalEquivalence, MapsWithDeletedDarts) {
  for (uint64_t seed = 0; seed < 30; ++seed) {
    Rng rng(seed);
    Map g = random_map(rng, Generator::SewSequence, 2 + int(seed % 2));
    // Delete a few darts (their partners become free in that dimension: possibly invalid, which
    // is fine here).
    const auto ds = g.darts();
    for (int k = 0; k < 3 && g.size() > 1; ++k) {
      const Dart d = ds[uniform(rng, 0, ds.size() - 1)];
      if (g.alive(d)) g.remove_dart(d);
    }
    if (seed % 3 == 0) corrupt(g, rng, 2, false);
    ASSERT_TRUE(g.has_holes() || g.size() <= 1);
    check_traversals(g, "holes seed=" + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
}
