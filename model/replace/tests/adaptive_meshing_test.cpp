// Adaptive hexahedral meshing by query-replace (Alg. 5) around an analytic sphere: valid maps,
// the level counts, and the balance (hexahedra sharing a vertex differ by at most one level).
#include <gtest/gtest.h>

#include <cmath>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/core/validity.hpp"
#include "model/replace/adaptive_hex_meshing.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

// The sphere's surface meets the box iff the nearest point of the box is inside the ball and the
// farthest is not.
bool sphere_meets(const Vec3& lo, const Vec3& hi, const Vec3& c, double r) {
  double near = 0, far = 0;
  for (int i = 0; i < 3; ++i) {
    const double n = std::max({lo[i] - c[i], 0.0, c[i] - hi[i]});
    const double f = std::max(std::abs(lo[i] - c[i]), std::abs(hi[i] - c[i]));
    near += n * n;
    far += f * f;
  }
  return near <= r * r && far >= r * r;
}

TEST(AdaptiveMeshing, SphereFourLevelsValidAndBalanced) {
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  FlaggedMap m = box_hexahedron({-1, -1, -1}, 2);
  const Vec3 centre{0.1, -0.05, 0.07};
  const auto levels = refine_adaptively(m, store, 4, [&](const Vec3& lo, const Vec3& hi) {
    return sphere_meets(lo, hi, centre, 0.7);
  });
  ASSERT_EQ(levels.size(), 4u);
  size_t volumes = 1;
  for (const MeshingLevel& l : levels) {
    EXPECT_GT(l.volume_replacements, 0u) << l.level;
    EXPECT_GT(l.face_replacements, 0u) << l.level;
    volumes += 7 * l.volume_replacements;
    EXPECT_EQ(l.volumes, volumes) << l.level;
  }
  EXPECT_EQ(levels[0].volume_replacements, 1u);
  EXPECT_EQ(levels[1].volume_replacements, 8u);  // the sphere meets all 8 octants
  EXPECT_TRUE(is_valid(m.map));
  // Balance: per volume its level (its size), compared over every vertex.
  const Map& g = m.map;
  std::vector<int> level(g.capacity(), -1);
  for (Dart rep : orbit_representatives(g, cell_type(g, 3))) {
    const std::vector<Dart> darts = orbit(g, cell_type(g, 3), rep);
    double lo = 1e9, hi = -1e9;
    for (Dart x : darts) {
      lo = std::min(lo, m.position[x][0]);
      hi = std::max(hi, m.position[x][0]);
    }
    for (Dart x : darts) level[x] = static_cast<int>(std::lround(std::log2(2 / (hi - lo))));
  }
  int finest = 0;
  for (Dart rep : orbit_representatives(g, vertex_orbit_type(g))) {
    int a = 99, b = -1;
    for (Dart x : orbit(g, vertex_orbit_type(g), rep)) {
      a = std::min(a, level[x]);
      b = std::max(b, level[x]);
    }
    ASSERT_LE(b - a, 1) << "vertex of dart " << rep;
    finest = std::max(finest, b);
  }
  EXPECT_EQ(finest, 4);
}

// The map is checked once, before the first level; each step keeps it valid (checked here after
// every level: the meshing to 1, 2, 3 and 4 levels, each from the box), and the levels of a longer
// run repeat those of a shorter one.
TEST(AdaptiveMeshing, EveryLevelLeavesAValidMap) {
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  const BoxTest meets = [](const Vec3& lo, const Vec3& hi) {
    return sphere_meets(lo, hi, {0.2, 0.1, -0.15}, 0.6);
  };
  std::vector<MeshingLevel> previous;
  for (int levels = 1; levels <= 4; ++levels) {
    FlaggedMap m = box_hexahedron({-1, -1, -1}, 2);
    const std::vector<MeshingLevel> run = refine_adaptively(m, store, levels, meets);
    EXPECT_TRUE(is_valid(m.map)) << levels << " levels";
    EXPECT_EQ(count_cells(m.map, 3), run.back().volumes);
    for (size_t l = 0; l < previous.size(); ++l) {
      EXPECT_EQ(run[l].volumes, previous[l].volumes) << levels << " levels, level " << l + 1;
      EXPECT_EQ(run[l].face_replacements, previous[l].face_replacements);
      EXPECT_EQ(run[l].balanced, previous[l].balanced);
    }
    previous = run;
  }
}

TEST(AdaptiveMeshing, RefusesAnInvalidMap) {
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  FlaggedMap m = box_hexahedron({0, 0, 0}, 1);
  m.map.set_alpha(2, 0, 5);  // one way only: alpha_2 is no longer an involution
  try {
    refine_adaptively(m, store, 1, [](const Vec3&, const Vec3&) { return true; });
    FAIL() << "an invalid map was refined";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidMap);
    EXPECT_NE(std::string(e.what()).find("not valid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gmr::replace
