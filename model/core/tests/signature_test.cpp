// BFS-word signatures (Damiand & Nivoliers §2.4 lifted to G-maps) and isomorphism.
#include "model/core/signature.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "model/core/builders.hpp"

using namespace gmr;

static Map permuted(const Map& g, unsigned seed) {
  std::vector<Dart> perm(g.capacity());
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(perm.begin(), perm.end(), rng);
  Map h(g.dimension(), g.kind());
  h.add_darts(g.capacity());
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
    for (Dart d = 0; d < g.capacity(); ++d) h.set_alpha(i, perm[d], perm[g.alpha(i, d)]);
  return h;
}

TEST(Signature, WordOfAnEdge) {
  // Free edge in a 2-G-map from dart 0: d1=0 (alpha0 -> 2, alpha1 -> 1, alpha2 -> 1), d2=1 ...
  Map g = make_free_edge(2);
  EXPECT_EQ(bfs_word(g, 0), (Word{2, 1, 1, 1, 2, 2}));
  EXPECT_EQ(bfs_labeling(g, 1), (std::vector<Dart>{1, 0}));
}

TEST(Signature, InvariantUnderRelabeling) {
  for (Map g : {make_cube(), make_stacked_cubes(), make_torus(3, 4), make_square_pyramid()}) {
    Map h = permuted(g, 7);
    EXPECT_EQ(signature(g), signature(h));
    EXPECT_TRUE(is_isomorphic(g, h));
  }
}

TEST(Signature, DistinguishesNonIsomorphic) {
  EXPECT_FALSE(is_isomorphic(make_cube(), make_prism(4)) && false);
  EXPECT_TRUE(is_isomorphic(make_cube(), make_prism(4)));  // a 4-prism is a cube
  EXPECT_FALSE(is_isomorphic(make_prism(5), make_torus(3, 5)));
  EXPECT_FALSE(is_isomorphic(make_grid(2, 3), make_grid(1, 6)));
  EXPECT_NE(signature(make_grid(2, 3)), signature(make_grid(1, 6)));
  EXPECT_FALSE(is_isomorphic(make_cube(2), make_cube(3)));
  // Same darts count, one link changed.
  Map a = make_polygon(6), b = make_polygon(6);
  b.unlink(1, 1);
  b.unlink(1, 5);
  b.link(1, 1, 5);
  EXPECT_FALSE(is_isomorphic(a, b));
}

TEST(Signature, FlagsRestrictMatches) {
  Map g = make_polygon(4);
  std::vector<uint32_t> f1(8, 0), f2(8, 0), f3(8, 0);
  f1[0] = 1;
  f2[2] = 1;  // another corner: same up to rotation
  f3[1] = 1;  // the other dart of edge 0 is also equivalent by reflection
  EXPECT_TRUE(is_isomorphic(g, g, &f1, &f2));
  EXPECT_TRUE(is_isomorphic(g, g, &f1, &f3));
  std::vector<uint32_t> f4(8, 0);
  f4[0] = 1;
  f4[1] = 1;  // two flagged darts
  EXPECT_FALSE(is_isomorphic(g, g, &f1, &f4));
  EXPECT_NE(signature(g, &f1), signature(g, &f4));
  EXPECT_NE(signature(g), signature(g, &f1));
}

TEST(Signature, SeveralComponents) {
  Map g = make_cube();
  Map t = make_tetrahedron();
  const Dart base = g.add_darts(t.capacity());
  for (int i = 0; i <= 2; ++i)
    for (Dart d = 0; d < t.capacity(); ++d) g.set_alpha(i, base + d, base + t.alpha(i, d));
  Map h = permuted(g, 3);
  EXPECT_EQ(signature(g).components.size(), 2u);
  EXPECT_TRUE(is_isomorphic(g, h));
}

TEST(Signature, OMaps) {
  Map o = orient(make_cube());
  EXPECT_TRUE(is_isomorphic(o, permuted(o, 11)));
  EXPECT_FALSE(is_isomorphic(o, orient(make_prism(5))));
}
