// Exhaustiveness (Damiand & Nivoliers 2022 §6.4): configuration classes by signatures,
// cross-checked by group orbits of the split-edge sets (no signature involved).
#include "model/replace/coverage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

// Orbits of the non-empty subsets of `edges` items under a group given as edge permutations.
size_t subset_orbits(size_t edges, const std::vector<std::vector<int>>& group) {
  std::set<uint32_t> canon;
  for (uint32_t mask = 1; mask < (1u << edges); ++mask) {
    uint32_t best = UINT32_MAX;
    for (const auto& g : group) {
      uint32_t image = 0;
      for (size_t e = 0; e < edges; ++e)
        if (mask >> e & 1) image |= 1u << g[e];
      best = std::min(best, image);
    }
    canon.insert(best);
  }
  return canon.size();
}

// The dihedral group of a k-gon acting on its edges in cyclic order (rotations first).
std::vector<std::vector<int>> polygon_group(int k, bool reflections) {
  std::vector<std::vector<int>> g;
  for (int r = 0; r < k; ++r)
    for (int s = 0; s < (reflections ? 2 : 1); ++s) {
      std::vector<int> p(k);
      for (int e = 0; e < k; ++e) p[e] = s ? ((r - e - 1) % k + k) % k : (e + r) % k;
      g.push_back(p);
    }
  return g;
}

// The cube's symmetries as signed axis permutations on vertex bits, acting on cube_edges().
std::vector<std::vector<int>> cube_group(bool reflections) {
  const auto edges = cube_edges();
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  std::vector<std::vector<int>> g;
  for (int p = 0; p < 6; ++p)
    for (int m = 0; m < 8; ++m) {
      const int sign =
          (p < 3 ? 1 : -1) * (__builtin_popcount(static_cast<unsigned>(m)) % 2 ? -1 : 1);
      if (!reflections && sign < 0) continue;
      auto image = [&](int v) {
        int w = 0;
        for (int i = 0; i < 3; ++i) w |= (((v >> perms[p][i]) & 1) ^ ((m >> i) & 1)) << i;
        return w;
      };
      std::vector<int> perm;
      for (const auto& [a, b] : edges) {
        std::array<int, 2> e{image(a), image(b)};
        std::sort(e.begin(), e.end());
        perm.push_back(static_cast<int>(std::find(edges.begin(), edges.end(), e) - edges.begin()));
      }
      g.push_back(perm);
    }
  return g;
}

CoverageReport coverage(const std::string& patterns, const ConfigurationSet& set, Mode mode) {
  PatternStore s(mode);
  for (auto& p : load_patterns(testing::patterns_dir(patterns))) s.add(std::move(p));
  return check_coverage(s, set);
}

TEST(Coverage, GroupsAreTheSymmetryGroups) {
  EXPECT_EQ(polygon_group(4, true).size(), 8u);
  EXPECT_EQ(cube_group(false).size(), 24u);
  EXPECT_EQ(cube_group(true).size(), 48u);
  for (const auto& p : cube_group(true)) EXPECT_EQ(std::set<int>(p.begin(), p.end()).size(), 12u);
}

TEST(Coverage, ConformalFacesCoverTheSquareConfigurations) {
  const ConfigurationSet set = generate_configurations("square-edges");
  ASSERT_EQ(set.configurations.size(), 15u);
  for (const auto& c : set.configurations) ASSERT_TRUE(is_valid(c.map.map));
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    const CoverageReport r = coverage("conformal-faces", set, mode);
    EXPECT_EQ(r.classes, subset_orbits(4, polygon_group(4, mode == Mode::Unoriented)));
    EXPECT_EQ(r.classes, 5u);
    EXPECT_TRUE(r.complete());
    EXPECT_TRUE(r.duplicates.empty());
    size_t covered = 0;
    for (size_t n : r.covering) covered += n;
    EXPECT_EQ(covered, 15u);
  }
}

TEST(Coverage, ReportsMissingClassesAndDuplicates) {
  const ConfigurationSet set = generate_configurations("square-edges");
  PatternStore s(Mode::Unoriented);
  s.add(testing::pattern_file("conformal-faces", "split4"));
  s.add(testing::pattern_file("conformal-faces", "split4"));
  const CoverageReport r = check_coverage(s, set);
  EXPECT_EQ(r.missing.size(), 4u);
  EXPECT_EQ(r.missing_configurations, 14u);
  ASSERT_EQ(r.duplicates.size(), 1u);
  EXPECT_EQ(r.covering, (std::vector<size_t>{1, 1}));
  // The triangle pattern covers the triangle with 3 split edges only.
  PatternStore t(Mode::Unoriented);
  t.add(testing::pattern_file("tet-to-hex", "triangle3"));
  const CoverageReport rt = check_coverage(t, generate_configurations("triangle-edges"));
  EXPECT_EQ(rt.configurations, 7u);
  EXPECT_EQ(rt.classes, subset_orbits(3, polygon_group(3, true)));
  EXPECT_EQ(rt.missing.size(), rt.classes - 1);
  EXPECT_THROW(generate_configurations("nonsense"), Error);
}

// Hexahedra with split edges: classes by signature = orbits of the rotation group (oriented) and
// of the full symmetry group (unoriented); a few pairs also checked by plain isomorphism.
TEST(Coverage, HexEdgesClassesMatchCubeSymmetryOrbits) {
  const ConfigurationSet set = generate_configurations("hex-edges");
  ASSERT_EQ(set.configurations.size(), 4095u);
  PatternStore none_u(Mode::Unoriented), none_o(Mode::Oriented);
  const CoverageReport u = check_coverage(none_u, set), o = check_coverage(none_o, set);
  EXPECT_EQ(u.classes, subset_orbits(12, cube_group(true)));
  EXPECT_EQ(o.classes, subset_orbits(12, cube_group(false)));
  EXPECT_LT(u.classes, o.classes);
  EXPECT_EQ(u.missing.size(), u.classes);
  // Unoriented classes agree with the core isomorphism test (flags as dart values) on the
  // configurations with 3 split edges.
  std::vector<const Configuration*> three;
  for (const auto& c : set.configurations)
    if (c.split.size() == 3) three.push_back(&c);
  std::vector<const Configuration*> reps;
  for (const Configuration* c : three) {
    bool found = false;
    for (const Configuration* r : reps)
      if (is_isomorphic(c->map.map, r->map.map, &c->map.flag, &r->map.flag)) found = true;
    if (!found) reps.push_back(c);
  }
  std::vector<std::vector<int>> full = cube_group(true);
  std::set<uint32_t> orbits3;
  for (const Configuration* c : three) {
    uint32_t best = UINT32_MAX;
    for (const auto& g : full) {
      uint32_t image = 0;
      for (int e : c->split) image |= 1u << g[e];
      best = std::min(best, image);
    }
    orbits3.insert(best);
  }
  EXPECT_EQ(reps.size(), orbits3.size());
}

// The conformal set of hexahedra (split edges + faces already cut in 4): the paper's 325 classes in
// oriented mode, cross-checked by the orbits of the cube's groups acting on (edges, cut faces).
TEST(Coverage, HexConformalClassesAreThePapers325InOrientedMode) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  const std::vector<std::vector<uint32_t>> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& c : set.configurations) ASSERT_TRUE(is_valid(c.map.map));
  // Orbits of (edge mask, cut-face mask) pairs; faces permuted through their corner sets.
  auto orbits = [&](bool reflections) {
    const auto group = cube_group(reflections);
    const auto edges = cube_edges();
    std::set<uint64_t> canon;
    for (const auto& c : set.configurations) {
      uint32_t em = 0, fm = 0;
      for (int x : c.split) (x < 100 ? em : fm) |= 1u << (x < 100 ? x : x - 100);
      uint64_t best = UINT64_MAX;
      for (const auto& g : group) {
        // The vertex map of g, read back from its action on edges (each corner is the common end
        // of its three edges' images).
        std::array<int, 8> vmap{};
        for (int v = 0; v < 8; ++v) {
          std::array<int, 8> count{};
          for (size_t e = 0; e < 12; ++e)
            if (edges[e][0] == v || edges[e][1] == v) {
              ++count[edges[g[e]][0]];
              ++count[edges[g[e]][1]];
            }
          vmap[v] = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
        }
        uint32_t ie = 0, ifm = 0;
        for (int e = 0; e < 12; ++e)
          if (em >> e & 1) ie |= 1u << g[e];
        for (int f = 0; f < 6; ++f)
          if (fm >> f & 1) {
            std::set<uint32_t> img;
            for (uint32_t v : faces[f]) img.insert(static_cast<uint32_t>(vmap[v]));
            for (int h = 0; h < 6; ++h)
              if (std::set<uint32_t>(faces[h].begin(), faces[h].end()) == img) ifm |= 1u << h;
          }
        best = std::min(best, uint64_t(ie) << 6 | ifm);
      }
      canon.insert(best);
    }
    return canon.size();
  };
  PatternStore none_u(Mode::Unoriented), none_o(Mode::Oriented);
  const CoverageReport u = check_coverage(none_u, set), o = check_coverage(none_o, set);
  EXPECT_EQ(o.classes, orbits(false));
  EXPECT_EQ(u.classes, orbits(true));
  EXPECT_EQ(o.classes, 325u);
  EXPECT_EQ(u.classes, 226u);
  EXPECT_EQ(set.configurations.size(), 6209u);
  // The generated boundaries carry the pattern files' flag convention: the 2x2x2 v-pattern covers
  // exactly the configuration with every edge split and every face cut.
  const CoverageReport h = coverage("hex-subdivision", set, Mode::Oriented);
  EXPECT_EQ(h.covering, (std::vector<size_t>{1, 0}));  // hex8, split4 (a face pattern)
  EXPECT_EQ(h.missing.size(), h.classes - 1);
}

// Marching cubes: the paper's 29 v-pattern boundaries in oriented mode; 26 unoriented (3 chiral
// pairs merge). Cross-check without signatures: pairwise isomorphism with flags (core Theorem 1
// test) gives the unoriented count.
TEST(Coverage, MarchingCubesBoundariesAreThePapers29) {
  const ConfigurationSet set = generate_configurations("marching-cubes");
  EXPECT_EQ(set.configurations.size(), 654u);
  for (const auto& c : set.configurations) ASSERT_TRUE(is_valid(c.map.map));
  PatternStore none_u(Mode::Unoriented), none_o(Mode::Oriented);
  const CoverageReport u = check_coverage(none_u, set), o = check_coverage(none_o, set);
  EXPECT_EQ(o.classes, 29u);
  EXPECT_EQ(u.classes, 26u);
  std::vector<const Configuration*> reps;
  for (const auto& c : set.configurations) {
    bool found = false;
    for (const Configuration* r : reps)
      if (!found && is_isomorphic(c.map.map, r->map.map, &c.map.flag, &r->map.flag)) found = true;
    if (!found) reps.push_back(&c);
  }
  EXPECT_EQ(reps.size(), u.classes);
}

}  // namespace
}  // namespace gmr::replace
