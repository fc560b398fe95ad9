// The random G-map generators: validity, determinism, and the guarantees of the edits.
#include "model/testing/random_maps.hpp"

#include <gtest/gtest.h>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"

using namespace gmr;
using namespace gmr::testing;

namespace {

std::vector<std::vector<Dart>> links_of(const Map& g) {
  std::vector<std::vector<Dart>> l;
  for (int i = 0; i <= g.dimension(); ++i) l.push_back(g.links(i));
  return l;
}

size_t free_count(const Map& g, int i) { return free_darts(g, i).size(); }

}  // namespace

TEST(RandomMaps, UniformIsPortableAndInRange) {
  Rng a(42), b(42);
  for (int k = 0; k < 1000; ++k) {
    const uint64_t x = uniform(a, 3, 9);
    EXPECT_GE(x, 3u);
    EXPECT_LE(x, 9u);
    EXPECT_EQ(x, uniform(b, 3, 9));
  }
  // Pinned values: the generators must give the same maps everywhere (no
  // std::uniform_int_distribution).
  Rng c(1);
  std::vector<uint64_t> got;
  for (int k = 0; k < 5; ++k) got.push_back(uniform(c, 0, 999));
  Rng d(1);
  std::vector<uint64_t> expect;
  for (int k = 0; k < 5; ++k) {
    uint64_t x;
    const uint64_t limit = UINT64_MAX - UINT64_MAX % 1000;
    do x = d();
    while (x >= limit);
    expect.push_back(x % 1000);
  }
  EXPECT_EQ(got, expect);
  EXPECT_THROW(uniform(c, 2, 1), Error);
}

TEST(RandomMaps, PermutationIsAPermutation) {
  Rng rng(7);
  auto p = random_permutation(rng, 100);
  std::vector<bool> hit(100, false);
  for (Dart x : p) {
    ASSERT_LT(x, 100u);
    EXPECT_FALSE(hit[x]);
    hit[x] = true;
  }
}

TEST(RandomMaps, GeneratorsGiveValidDeterministicMaps) {
  for (int n = 0; n <= 4; ++n) {
    for (Generator gen : generators_for(n)) {
      for (uint64_t seed = 0; seed < 40; ++seed) {
        Rng r1(seed), r2(seed);
        Map g = random_map(r1, gen, n);
        Map h = random_map(r2, gen, n);
        SCOPED_TRACE(std::string(to_string(gen)) + " n=" + std::to_string(n) +
                     " seed=" + std::to_string(seed));
        EXPECT_EQ(g.dimension(), n);
        EXPECT_FALSE(g.has_holes());
        const auto rep = check_validity(g, 3);
        ASSERT_TRUE(rep.ok()) << to_text(rep.violations.front());
        EXPECT_EQ(links_of(g), links_of(h));
      }
    }
  }
}

TEST(RandomMaps, GluedPolygonsAreConnectedWithoutMonogons) {
  for (uint64_t seed = 0; seed < 50; ++seed) {
    Rng rng(seed);
    GluedPolygonsOptions o;
    o.min_sides = 2;
    o.n = 2 + static_cast<int>(seed % 2);
    Map g = random_glued_polygons(rng, o);
    EXPECT_TRUE(is_valid(g));
    EXPECT_EQ(count_components(g), 1u) << seed;
  }
}

TEST(RandomMaps, PolycubesAreConnectedAndSized) {
  for (uint64_t seed = 0; seed < 20; ++seed) {
    Rng rng(seed);
    auto vox = random_voxels(rng, 1 + seed % 7);
    EXPECT_EQ(vox.size(), 1 + seed % 7);
    Map g = make_polycube(vox);
    EXPECT_EQ(g.size(), 48 * vox.size());
    EXPECT_EQ(count_components(g), 1u);
    EXPECT_EQ(count_cells(g, 3), vox.size());
  }
}

TEST(RandomMaps, SewSequencesUseEveryDimension) {
  // Over many seeds, 3D sew sequences sew in every dimension 0..3 (beyond the pool's own links).
  std::vector<size_t> sewn(4, 0);
  for (uint64_t seed = 0; seed < 60; ++seed) {
    Rng rng(seed);
    SewSequenceOptions o;
    o.n = 3;
    o.steps = 30;
    Map g = random_sewn_cells(rng, o);
    ASSERT_TRUE(is_valid(g));
    for (int i = 0; i <= 3; ++i) sewn[i] += g.size() - free_count(g, i);
  }
  for (int i = 0; i <= 3; ++i) EXPECT_GT(sewn[i], 0u) << i;
}

TEST(RandomMaps, RelabelIsAnIsomorphicCopy) {
  for (uint64_t seed = 0; seed < 30; ++seed) {
    Rng rng(seed);
    Map g = random_map(rng, Generator::SewSequence, 2 + static_cast<int>(seed % 2));
    const auto perm = random_permutation(rng, g.capacity());
    Map h = permute_darts(g, perm);
    ASSERT_TRUE(is_valid(h));
    for (int i = 0; i <= g.dimension(); ++i)
      for (Dart d = 0; d < g.capacity(); ++d) EXPECT_EQ(h.alpha(i, perm[d]), perm[g.alpha(i, d)]);
    EXPECT_TRUE(is_isomorphic(g, h));
  }
  Map g = make_cube(2);
  EXPECT_THROW(permute_darts(g, {0, 1}), Error);
  std::vector<Dart> bad(g.capacity(), 0);
  EXPECT_THROW(permute_darts(g, bad), Error);
}

TEST(RandomMaps, RelabelKeepsHoles) {
  Map g = make_polygon(4);
  g.add_darts(2);
  g.link(0, 8, 9);
  g.remove_dart(8);
  g.remove_dart(9);
  Rng rng(3);
  const auto perm = random_permutation(rng, g.capacity());
  Map h = permute_darts(g, perm);
  EXPECT_EQ(h.size(), 8u);
  EXPECT_FALSE(h.alive(perm[8]));
  EXPECT_FALSE(h.alive(perm[9]));
  EXPECT_TRUE(is_valid(h));
  EXPECT_TRUE(is_isomorphic(g, h));
}

TEST(RandomMaps, MutationIsValidAndNotIsomorphic) {
  for (int n = 0; n <= 3; ++n) {
    for (Generator gen : generators_for(n)) {
      for (uint64_t seed = 0; seed < 25; ++seed) {
        Rng rng(seed);
        const Map g = random_map(rng, gen, n);
        Map h = g;
        const Mutation m = mutate_one_link(h, rng);
        SCOPED_TRACE(std::string(to_string(gen)) + " n=" + std::to_string(n) +
                     " seed=" + std::to_string(seed) + " " + m.str());
        if (g.size() < 2) {
          EXPECT_EQ(m.kind, Mutation::Kind::None);
          continue;
        }
        ASSERT_NE(m.kind, Mutation::Kind::None);
        EXPECT_TRUE(is_valid(h));
        EXPECT_EQ(h.size(), g.size());
        EXPECT_NE(free_count(h, m.dim), free_count(g, m.dim));
        EXPECT_FALSE(is_isomorphic(g, h));
      }
    }
  }
  Map two(2);
  two.add_darts(2);
  Rng rng(0);
  EXPECT_EQ(mutate_one_link(two, rng).kind, Mutation::Kind::Sew);
  EXPECT_TRUE(is_valid(two));
  EXPECT_EQ(count_components(two), 1u);
}

TEST(RandomMaps, ResewIsValid) {
  size_t changed = 0;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    Rng rng(seed);
    const Map g = random_map(rng, seed % 2 ? Generator::GluedPolygons : Generator::SewSequence,
                             2 + int(seed % 3 == 0));
    Map h = g;
    const Mutation m = resew_one_link(h, rng);
    EXPECT_TRUE(is_valid(h)) << m.str();
    EXPECT_EQ(h.size(), g.size());
    if (m.kind == Mutation::Kind::None)
      EXPECT_EQ(links_of(g), links_of(h));
    else
      ++changed;
  }
  EXPECT_GT(changed, 30u);
}

// Random O-maps: both constructions give valid O-maps, deterministically; the oriented components
// of glued polygons / polycubes have half the darts of their orientable components.
TEST(RandomMaps, RandomOMapsAreValid) {
  size_t with_boundary = 0, nonempty = 0;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    Rng r1(seed), r2(seed);
    const Map p = random_permutation_omap(r1);
    ASSERT_TRUE(p.is_omap());
    ASSERT_TRUE(is_valid(p)) << "seed " << seed;
    ASSERT_TRUE(is_isomorphic(p, random_permutation_omap(r2)));
    for (Dart d : p.darts()) with_boundary += p.alpha(2, d) == d;
    Rng r3(seed);
    GluedPolygonsOptions go;
    go.max_faces = 4;
    const Map g = seed % 2 ? random_glued_polygons(r3, go)
                           : double_along_boundary(random_polycube(r3, {1, 3}));
    const Map o = oriented_components(g);
    ASSERT_TRUE(o.is_omap());
    ASSERT_EQ(o.dimension(), g.dimension());
    ASSERT_TRUE(is_valid(o)) << "seed " << seed;
    ASSERT_LE(2 * o.size(), g.size());
    if (seed % 2 == 0) {
      ASSERT_TRUE(is_valid(g));
      ASSERT_TRUE(is_closed(g));
      ASSERT_EQ(2 * o.size(), g.size());  // doubled polycubes are orientable
    }
    nonempty += o.size() > 0;
  }
  EXPECT_GT(with_boundary, 0u);
  EXPECT_GT(nonempty, 120u);  // measured 142 of 200: non-orientable glued polygons are skipped
}
