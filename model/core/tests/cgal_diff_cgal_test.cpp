// Differential test against CGAL::Generalized_map (CGAL 5.5): on a few hundred random G-maps of
// dimensions 2, 3 and 4 (every generator of random_maps.hpp), the same map is built in CGAL and
// both libraries are compared on
//   * validity (gmr::is_valid vs CGAL is_valid) and the number of i-cells for each i and of
//     connected components (gmr::count_all_cells + count_components vs CGAL count_all_cells);
//   * isomorphism verdicts (gmr::is_isomorphic and gmr::signature equality vs CGAL
//     is_isomorphic_to / are_cc_isomorphic) on three kinds of pairs: a random relabeling of the
//     darts (isomorphic), mutate_one_link + relabeling (not isomorphic), resew_one_link +
//     relabeling (either; the two libraries must agree);
//   * deliberately invalid maps (an alpha_i that is not an involution, a broken cycle constraint
//     alpha_i alpha_j alpha_i alpha_j = id) that both must reject.
// A larger sweep (more seeds, bigger maps) is cgal_diff_cgal_slow_test.cpp (label slow).
#include "model/core/builders.hpp"
#include "model/core/sew.hpp"
#include "model/core/tests/cgal_diff.hpp"

using namespace gmr;
using namespace gmr::testing;

using namespace cgal_diff;
using gmr::testing::Generator;
using gmr::testing::Rng;

namespace {

void report(const char* what, const Stats& st) {
  std::cout << "[cgal-diff] " << what << ": " << st.str() << "\n";
}

// compare_one on `seeds` random maps of the generator, the statistics reported as `what`.
template <unsigned N>
Stats sweep(Generator gen, uint64_t seeds, const char* what) {
  Stats st;
  for (uint64_t s = 0; s < seeds; ++s) {
    Rng rng(s * 7919 + N * 101 + static_cast<uint64_t>(gen));
    const Map g = gmr::testing::random_map(rng, gen, static_cast<int>(N));
    SCOPED_TRACE(std::string(gmr::testing::to_string(gen)) + " n=" + std::to_string(N) +
                 " seed=" + std::to_string(s));
    compare_one<N>(g, rng, st);
    if (::testing::Test::HasFatalFailure()) break;
  }
  report(what, st);
  return st;
}

}  // namespace

TEST(CgalDiff, GluedPolygons2D) {
  const Stats st = sweep<2>(Generator::GluedPolygons, 80, "glued polygons n=2");
  EXPECT_GT(st.resew_iso + st.resew_non_iso, 40u);
  EXPECT_GT(st.broken_cycle, 40u);
}

TEST(CgalDiff, GluedPolygons3D) { sweep<3>(Generator::GluedPolygons, 40, "glued polygons n=3"); }

TEST(CgalDiff, SewSequence2D) {
  const Stats st = sweep<2>(Generator::SewSequence, 80, "sew sequences n=2");
  EXPECT_GT(st.multi_component, 10u);
}

TEST(CgalDiff, SewSequence3D) { sweep<3>(Generator::SewSequence, 80, "sew sequences n=3"); }

TEST(CgalDiff, Polycube3D) {
  const Stats st = sweep<3>(Generator::Polycube, 50, "polycubes n=3");
  EXPECT_GT(st.broken_cycle, 40u);
}

TEST(CgalDiff, SewSequence4D) { sweep<4>(Generator::SewSequence, 30, "sew sequences n=4"); }

TEST(CgalDiff, ResewnRandomMaps) {
  // Random resews are mostly non-isomorphic; this sweep only adds volume to the agreement check.
  Stats st;
  for (uint64_t s = 0; s < 60; ++s) {
    Rng rng(s + 424242);
    compare_one<2>(
        gmr::testing::random_map(rng, s % 2 ? Generator::GluedPolygons : Generator::SewSequence, 2),
        rng, st);
  }
  report("resewn random maps n=2", st);
  EXPECT_GT(st.resew_non_iso, 0u);
}

namespace {

// Re-glues the i-sewn orbit of d with a twist: e = alpha_i(d); i-unsew d; i-sew d to alpha_k(e)
// (k in the i-sew orbit type, so alpha_k(e) was in the orbit sewn to d's). Returns false (and
// leaves g unchanged) when not possible.
bool twist(Map& g, int i, int k, Dart d) {
  if (g.is_free(i, d)) return false;
  const Dart e = g.alpha(i, d), x = g.alpha(k, e);
  if (x == e) return false;
  gmr::unsew(g, i, d);
  if (!gmr::is_sewable(g, i, d, x)) {
    gmr::sew(g, i, d, e);
    return false;
  }
  gmr::sew(g, i, d, x);
  return true;
}

// The same twist at two random darts of `base`, each result relabeled: on a regular map (its
// automorphisms act transitively on darts: cube, tetrahedron, square torus) the results are
// isomorphic; on other maps it depends on the two darts. gmr and CGAL must agree; returns the
// number of isomorphic / non-isomorphic pairs.
template <unsigned N>
std::pair<size_t, size_t> twisted_pairs(const Map& base, int i, int k, uint64_t seed, size_t pairs,
                                        bool regular) {
  Rng rng(seed);
  size_t iso = 0, non = 0;
  const auto ds = base.darts();
  for (size_t p = 0; p < pairs; ++p) {
    Map a = base, b = base;
    const Dart da = ds[gmr::testing::uniform(rng, 0, ds.size() - 1)],
               db = ds[gmr::testing::uniform(rng, 0, ds.size() - 1)];
    if (!twist(a, i, k, da) || !twist(b, i, k, db)) continue;
    b = gmr::testing::permute_darts(b, gmr::testing::random_permutation(rng, b.capacity()));
    CMap<N> ca, cb;
    to_cgal<N>(a, ca);
    to_cgal<N>(b, cb);
    EXPECT_TRUE(gmr::is_valid(a) && gmr::is_valid(b));
    EXPECT_TRUE(cgal_is_valid(ca) && cgal_is_valid(cb));
    EXPECT_EQ(gmr_cells(b), cgal_cells<N>(cb));
    const bool gi = gmr::is_isomorphic(a, b), ci = cgal_isomorphic<N>(ca, cb);
    EXPECT_EQ(gi, ci) << "darts " << da << ", " << db;
    EXPECT_EQ(gmr::signature(a) == gmr::signature(b), ci);
    if (regular) {
      EXPECT_TRUE(ci) << "darts " << da << ", " << db;
    }
    ++(ci ? iso : non);
  }
  return {iso, non};
}

}  // namespace

TEST(CgalDiff, TwistedPairsOccurBothWays) {
  // Hard pairs: same darts, same cell counts up to the twist location.
  size_t iso = 0, non = 0;
  auto add = [&](std::pair<size_t, size_t> r) {
    iso += r.first;
    non += r.second;
  };
  add(twisted_pairs<2>(gmr::make_cube(2), 2, 0, 1, 20, true));
  add(twisted_pairs<2>(gmr::make_tetrahedron(2), 2, 0, 2, 20, true));
  add(twisted_pairs<2>(gmr::make_torus(4, 4), 2, 0, 3, 20, true));
  add(twisted_pairs<2>(gmr::make_prism(5), 2, 0, 4, 30, false));
  add(twisted_pairs<2>(gmr::make_square_pyramid(), 2, 0, 5, 30, false));
  add(twisted_pairs<2>(gmr::make_grid(3, 2), 2, 0, 6, 30, false));
  add(twisted_pairs<3>(gmr::make_stacked_cubes(), 3, 1, 7, 30, false));
  add(twisted_pairs<3>(gmr::make_polycube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}), 3, 0, 8,
                       30, false));
  std::cout << "[cgal-diff] twisted pairs: " << iso << " isomorphic, " << non << " not\n";
  EXPECT_GT(iso, 60u);
  EXPECT_GT(non, 20u);
}

TEST(CgalDiff, NamedInvalidMaps) {
  // A square whose alpha_0 is not an involution at dart 0.
  {
    Map g = gmr::make_polygon(4);
    g.set_alpha(0, 0, 2);
    CMap<2> c;
    to_cgal<2>(g, c);
    EXPECT_FALSE(gmr::is_valid(g));
    EXPECT_FALSE(cgal_is_valid(c));
  }
  // Two quads 2-sewn along an edge, then one of the two 2-links of the edge removed: the
  // 0202-path from the remaining sewn dart does not close.
  {
    Map g = gmr::make_grid(2, 1);
    CMap<2> c;
    to_cgal<2>(g, c);
    ASSERT_TRUE(gmr::is_valid(g));
    ASSERT_TRUE(cgal_is_valid(c));
    Dart d = gmr::kNoDart;
    g.for_each_dart([&](Dart x) {
      if (d == gmr::kNoDart && !g.is_free(2, x)) d = x;
    });
    ASSERT_NE(d, gmr::kNoDart);
    g.unlink(2, g.alpha(0, d));
    to_cgal<2>(g, c);
    EXPECT_FALSE(gmr::is_valid(g));
    EXPECT_FALSE(cgal_is_valid(c));
  }
  // Stacked cubes with one 3-link of the shared face removed: C(0,3) and C(1,3) break.
  {
    Map g = gmr::make_stacked_cubes();
    Dart d = gmr::kNoDart;
    g.for_each_dart([&](Dart x) {
      if (d == gmr::kNoDart && !g.is_free(3, x)) d = x;
    });
    g.unlink(3, d);
    CMap<3> c;
    to_cgal<3>(g, c);
    EXPECT_FALSE(gmr::is_valid(g));
    EXPECT_FALSE(cgal_is_valid(c));
  }
}
