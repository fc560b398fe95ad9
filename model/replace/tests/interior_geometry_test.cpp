// Geometry of replaced interiors (Damiand & Nivoliers 2022 §5.2): mean value coordinates reproduce
// affine maps, so subdividing an affine image of the unit cube puts every new vertex at the affine
// image of its grid point.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "model/core/position.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/off.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::replace {
namespace {

// x -> A x + t, a shear with scaling.
Vec3 affine(const Vec3& p) {
  return {2 * p[0] + 0.5 * p[1] + 1, -0.3 * p[0] + 1.5 * p[1] + 0.2 * p[2] - 2,
          0.7 * p[2] + 0.1 * p[0] + 3};
}

// The unit cube of tools/data/cube.off, moved by `affine`, every dart flagged, lifted to dimension
// n.
FlaggedMap affine_cube(int n) {
  const EmbeddedMap pm = io::read_off_file(::gmr::testing::source_path("tools/data/cube.off"));
  FlaggedMap m{lift(pm.map, n), {}, {}};
  m.flag.assign(m.map.capacity(), 1);
  m.position.resize(m.map.capacity());
  m.map.for_each_dart([&](Dart d) { m.position[d] = affine(pm.position().get(d)); });
  return m;
}

// Every vertex is the affine image of a point of the grid {0, 1/2, 1}^3; returns the distinct
// grid points met.
size_t grid_points(const FlaggedMap& m) {
  std::set<std::array<int, 3>> seen;
  for (Dart v : orbit_representatives(m.map, vertex_orbit_type(m.map))) {
    bool found = false;
    for (int g = 0; g < 27 && !found; ++g) {
      const Vec3 p = affine({(g % 3) / 2.0, (g / 3 % 3) / 2.0, (g / 9) / 2.0});
      if (std::abs(p[0] - m.position[v][0]) + std::abs(p[1] - m.position[v][1]) +
              std::abs(p[2] - m.position[v][2]) <
          1e-9) {
        found = true;
        seen.insert({g % 3, g / 3 % 3, g / 9});
      }
    }
    EXPECT_TRUE(found) << "vertex of dart " << v << " at " << m.position[v][0] << " "
                       << m.position[v][1] << " " << m.position[v][2];
    // All darts of a vertex share its position.
    for (Dart x : orbit(m.map, vertex_orbit_type(m.map), v))
      EXPECT_EQ(m.position[x], m.position[v]);
  }
  return seen.size();
}

TEST(InteriorGeometry, FacePatternsReproduceAffineMaps) {
  FlaggedMap m = affine_cube(2);
  testing::split_each_edge(m, 2);
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  EXPECT_EQ(query_replace(m, store, 2).replaced(), 6u);
  EXPECT_EQ(grid_points(m), 26u);  // 8 corners, 12 edge midpoints, 6 face centres
  // The positions go out as the embedding "position" (one value per vertex).
  const EmbeddedMap f = to_embedded_map(m);
  ASSERT_NE(f.find(kPositionName), nullptr);
  EXPECT_TRUE(f.find(kPositionName)->check(f.map).empty());
}

TEST(InteriorGeometry, VolumePatternsReproduceAffineMaps) {
  FlaggedMap m = affine_cube(3);
  testing::split_each_edge(m, 2);
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  query_replace(m, store, 2);
  EXPECT_EQ(query_replace(m, store, 3).replaced(), 1u);
  EXPECT_TRUE(is_valid(m.map));
  EXPECT_EQ(grid_points(m), 27u);  // and the cube's centre
}

// Any tetrahedron is an affine image of the pattern's: the new vertices are the edge midpoints,
// the face centroids and the centroid (Fig. 16).
TEST(InteriorGeometry, TetrahedronToHexahedraPlacesCentroids) {
  const std::vector<Vec3> corner = {{0.3, -1, 2}, {4, 0.5, 1}, {1, 3, -0.5}, {0.5, 1, 5}};
  FlaggedMap m{
      lift(surface_from_faces({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, 4), 3), {}, {}};
  std::vector<uint32_t> vertex;
  surface_from_faces({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, 4, {}, &vertex);
  m.flag.assign(m.map.capacity(), 1);
  m.position.resize(m.map.capacity());
  m.map.for_each_dart([&](Dart d) { m.position[d] = corner[vertex[d]]; });
  testing::split_each_edge(m, 2);
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("tet-to-hex"))) store.add(std::move(p));
  query_replace(m, store, 2);
  EXPECT_EQ(query_replace(m, store, 3).replaced(), 1u);
  // Expected points: centroids of every non-empty subset of corners (1: corners, 2: midpoints,
  // ...).
  std::vector<Vec3> expected;
  for (int s = 1; s < 16; ++s) {
    Vec3 c{0, 0, 0};
    const int k = __builtin_popcount(static_cast<unsigned>(s));
    for (int v = 0; v < 4; ++v)
      if (s >> v & 1)
        for (int i = 0; i < 3; ++i) c[i] += corner[v][i] / k;
    expected.push_back(c);
  }
  const auto reps = orbit_representatives(m.map, vertex_orbit_type(m.map));
  EXPECT_EQ(reps.size(), 15u);
  for (Dart v : reps) {
    bool found = false;
    for (const Vec3& e : expected)
      found |= std::abs(e[0] - m.position[v][0]) + std::abs(e[1] - m.position[v][1]) +
                   std::abs(e[2] - m.position[v][2]) <
               1e-9;
    EXPECT_TRUE(found) << "vertex of dart " << v;
  }
}

}  // namespace
}  // namespace gmr::replace
