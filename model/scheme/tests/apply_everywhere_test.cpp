// apply_everywhere: Jerboa-style application of a one-hook scheme at every dart (thesis §6.3.4).
#include "model/scheme/apply_everywhere.hpp"

#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/scheme/tests/scheme_fixtures.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::fixtures;

namespace {

// The disjoint union of a and b (b's darts shifted by a.capacity()); both without holes.
Map disjoint_union(const Map& a, const Map& b) {
  Map g = a;
  const Dart off = g.add_darts(b.capacity());
  for (Dart d = 0; d < b.capacity(); ++d)
    for (int i = 0; i <= b.dimension(); ++i) g.set_alpha(i, off + d, off + b.alpha(i, d));
  return g;
}

// Applies the scheme at the given hooks one after the other, as apply_everywhere reports them.
Map replay(const Map& g0, const RuleScheme& s, const std::vector<Dart>& hooks) {
  Map g = g0;
  const SchemeEngine e(s);
  for (Dart d : hooks) EXPECT_TRUE(scheme::apply(e, g, {d}).applied);
  return g;
}

bool same_links(const Map& a, const Map& b) {
  if (a.capacity() != b.capacity() || a.size() != b.size()) return false;
  for (Dart d = 0; d < a.capacity(); ++d) {
    if (a.alive(d) != b.alive(d)) return false;
    if (!a.alive(d)) continue;
    for (int i = 0; i <= a.dimension(); ++i)
      if (a.alpha(i, d) != b.alpha(i, d)) return false;
  }
  return true;
}

}  // namespace

TEST(ApplyEverywhere, QuadSubdivisionOncePerComponent) {
  const Map cube = make_cube(2);
  Map g = cube;
  const EverywhereApplication one = apply_everywhere(SchemeEngine(quad_subdivision()), g);
  ASSERT_EQ(one.count(), 1u);
  EXPECT_EQ(one.hooks, std::vector<Dart>{0});
  EXPECT_EQ(g.size(), 192u);  // as `gmr apply --all quad_subdivision.json cube.off`: 48 -> 192
  EXPECT_EQ(one.darts_added(), 144u);
  EXPECT_EQ(one.darts_deleted(), 0u);
  EXPECT_TRUE(is_valid(g));

  const Map two_cubes = disjoint_union(cube, cube);
  Map h = two_cubes;
  const EverywhereApplication two = apply_everywhere(SchemeEngine(quad_subdivision()), h);
  ASSERT_EQ(two.count(), 2u);
  EXPECT_EQ(two.hooks, (std::vector<Dart>{0, 48}));
  EXPECT_EQ(h.size(), 384u);
  EXPECT_TRUE(is_valid(h));
  EXPECT_TRUE(same_links(h, replay(two_cubes, quad_subdivision(), two.hooks)));
}

TEST(ApplyEverywhere, VertexInsertionOncePerEdge) {
  const Map cube = make_cube(2);
  Map g = cube;
  const EverywhereApplication all = apply_everywhere(SchemeEngine(vertex_insertion()), g);
  ASSERT_EQ(all.count(), 12u);  // the cube's 12 edges
  EXPECT_EQ(all.darts_added(), 48u);
  EXPECT_EQ(g.size(), 96u);
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(all.applications.front().orbit_size(), 4u);  // tables kept by default
  for (size_t k = 1; k < all.hooks.size(); ++k) EXPECT_LT(all.hooks[k - 1], all.hooks[k]);
  EXPECT_TRUE(same_links(g, replay(cube, vertex_insertion(), all.hooks)));

  Map h = cube;
  const EverywhereApplication lean =
      apply_everywhere(SchemeEngine(vertex_insertion()), h, {.keep_tables = false});
  EXPECT_EQ(lean.hooks, all.hooks);
  EXPECT_TRUE(lean.applications.front().match.empty());
  EXPECT_TRUE(same_links(g, h));
}

TEST(ApplyEverywhere, NotApplicableAnywhereAndMisuse) {
  RuleScheme r = vertex_insertion();
  r.right.nodes[1].label = ot("<_,2>");  // breaks incident arcs: never applicable
  Map g = make_cube(2);
  const EverywhereApplication none = apply_everywhere(SchemeEngine(r), g);
  EXPECT_EQ(none.count(), 0u);
  EXPECT_FALSE(none.last_failure.applied);
  EXPECT_EQ(none.last_failure.reason, NotApplicableReason::NotCombinatorial);
  EXPECT_EQ(g.size(), 48u);

  Map empty(2);
  const EverywhereApplication nothing = apply_everywhere(SchemeEngine(quad_subdivision()), empty);
  EXPECT_EQ(nothing.count(), 0u);
  EXPECT_EQ(nothing.last_failure.reason, NotApplicableReason::None);

  Map c = make_cube(2);
  EXPECT_THROW(apply_everywhere(SchemeEngine(sew2()), c), Error);  // two hooks
}
