// The whole-component path of apply_everywhere (component_rewrite.hpp) against one
// scheme::apply per visited dart: the same map dart for dart, the same applications.
#include "model/scheme/component_rewrite.hpp"

#include <gtest/gtest.h>

#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/scheme/tests/scheme_fixtures.hpp"
#include "model/testing/random_maps.hpp"
#include "model/testing/random_schemes.hpp"

using namespace gmr;
using namespace gmr::scheme;
namespace gt = gmr::testing;

namespace {

// Same darts alive, same links, same free list order (later add_dart reuse).
void expect_same_map(const Map& a, const Map& b, const std::string& where) {
  ASSERT_EQ(a.capacity(), b.capacity()) << where;
  ASSERT_EQ(a.size(), b.size()) << where;
  for (Dart d = 0; d < a.capacity(); ++d) {
    ASSERT_EQ(a.alive(d), b.alive(d)) << where << ", dart " << d;
    if (!a.alive(d)) continue;
    for (int i = 0; i <= a.dimension(); ++i)
      ASSERT_EQ(a.alpha(i, d), b.alpha(i, d)) << where << ", dart " << d;
  }
  Map ca = a, cb = b;  // the next reused indices tell the free lists apart
  while (ca.has_holes()) ASSERT_EQ(ca.add_dart(), cb.add_dart()) << where;
}

void expect_same_applications(const EverywhereApplication& x, const EverywhereApplication& y,
                              const std::string& where) {
  ASSERT_EQ(x.count(), y.count()) << where;
  EXPECT_EQ(x.hooks, y.hooks) << where;
  for (size_t k = 0; k < x.count(); ++k) {
    EXPECT_EQ(x.applications[k].orbit, y.applications[k].orbit) << where;
    EXPECT_EQ(x.applications[k].match, y.applications[k].match) << where;
    EXPECT_EQ(x.applications[k].comatch, y.applications[k].comatch) << where;
    EXPECT_EQ(x.applications[k].darts_added, y.applications[k].darts_added) << where;
    EXPECT_EQ(x.applications[k].darts_deleted, y.applications[k].darts_deleted) << where;
  }
}

void compare_paths(const Map& g0, const RuleScheme& s, const std::string& where) {
  const SchemeEngine e(s);
  ASSERT_TRUE(rewrites_whole_components(e, g0)) << where;
  Map a = g0, b = g0;
  const EverywhereApplication x = apply_everywhere(e, a, {.path = EverywherePath::ByComponents});
  const EverywhereApplication y = apply_everywhere(e, b, {.path = EverywherePath::AtEachDart});
  expect_same_map(a, b, where);
  expect_same_applications(x, y, where);
  Map c = g0;  // the automatic choice takes this path
  const EverywhereApplication z = apply_everywhere(e, c, {.keep_tables = false});
  expect_same_map(c, b, where + " (apply_everywhere)");
  EXPECT_EQ(z.hooks, y.hooks) << where;
}

TEST(ComponentRewrite, QuadSubdivisionOfGluedPolygonsIsTheEngineResult) {
  for (uint64_t seed = 0; seed < 40; ++seed) {
    gt::Rng rng(seed);
    gt::GluedPolygonsOptions opt;
    opt.connected = seed % 2 == 0;
    const Map g = gt::random_glued_polygons(rng, opt);
    compare_paths(g, fixtures::quad_subdivision(), "seed " + std::to_string(seed));
  }
}

TEST(ComponentRewrite, RandomCopiesSchemesOnSewnCellsAreTheEngineResult) {
  // Random schemes of the whole-component form (hook preserved or deleted, 1..4 R nodes) on maps
  // of several components, some with deleted darts.
  size_t with_holes = 0;
  for (uint64_t seed = 0; seed < 120; ++seed) {
    gt::Rng rng(1000 + seed);
    const int n = static_cast<int>(gt::uniform(rng, 0, 3));
    const RuleScheme s = gt::random_copies_scheme(rng, n, 4);
    gt::SewSequenceOptions opt;
    opt.n = n;
    Map g = gt::random_sewn_cells(rng, opt);
    if (seed % 3 == 0 && g.size() > 2) {  // a hole: an isolated dart removed, or none
      for (Dart d = 0; d < g.capacity(); ++d) {
        bool isolated = true;
        for (int i = 0; i <= n; ++i) isolated = isolated && g.is_free(i, d);
        if (isolated) {
          g.remove_dart(d);
          ++with_holes;
          break;
        }
      }
    }
    compare_paths(g, s, "seed " + std::to_string(seed) + ", scheme " + s.name);
    Map r = g;
    apply_everywhere(SchemeEngine(s), r);
    EXPECT_TRUE(check_validity(r).ok()) << "seed " << seed;
  }
  EXPECT_GT(with_holes, 0u);
}

TEST(ComponentRewrite, OtherSchemesAndMapsTakeTheGeneralPath) {
  const Map square = make_polygon(4);
  EXPECT_FALSE(rewrites_whole_components(SchemeEngine(fixtures::vertex_insertion()),
                                         square));  // L label <0>
  Map g3(3);
  g3.add_darts(2);
  EXPECT_FALSE(
      rewrites_whole_components(SchemeEngine(fixtures::quad_subdivision()), g3));  // dimension
  Map sq = square;
  EXPECT_THROW(apply_everywhere(SchemeEngine(fixtures::vertex_insertion()), sq,
                                {.keep_tables = false, .path = EverywherePath::ByComponents}),
               Error);
}

}  // namespace

namespace {

TEST(ComponentRewrite, RandomSchemesOfTheWholeComponentFormAreTheEngineResult) {
  // Arbitrary random schemes (explicit arcs, `_` in R labels, added and deleted nodes): those
  // whose L is the hook alone with every dimension are compared.
  size_t compared = 0;
  for (uint64_t seed = 0; seed < 3000 && compared < 60; ++seed) {
    gt::Rng rng(5000 + seed);
    gt::RandomSchemeOptions so;
    so.n = static_cast<int>(gt::uniform(rng, 1, 3));
    so.second_left_percent = 0;
    RuleScheme s = gt::random_scheme(rng, so);
    gt::SewSequenceOptions mo;
    mo.n = so.n;
    const Map g = gt::random_sewn_cells(rng, mo);
    const SchemeEngine e(s);
    if (!rewrites_whole_components(e, g)) continue;
    ++compared;
    compare_paths(g, s, "seed " + std::to_string(seed));
  }
  EXPECT_GE(compared, 20u);
}

}  // namespace
