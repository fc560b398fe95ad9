// v-patterns built as cones over closed cell boundaries (cone_pattern.hpp), and the conformal
// volume pattern set: one cone per hex-conformal configuration class (Damiand & Nivoliers 2022
// §7.3: 325 oriented classes), checked for duplicates and coverage in both modes and applied.
#include "model/replace/cone_pattern.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/replace/coverage.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/replace/unit_hex_positions.hpp"

namespace gmr::replace {
namespace {

TEST(ConePattern, ConeOfTheCubeIsSixPyramidsWithTheCubeAsBoundary) {
  FlaggedMap cube = testing::all_flagged(make_cube(2));
  const FlaggedMap cone = cone_of_surface(cube);
  EXPECT_TRUE(is_valid(cone.map));
  EXPECT_EQ(cone.map.size(), 4 * cube.map.size());
  const auto cells = count_all_cells(cone.map);
  EXPECT_EQ(cells[0], 9u);       // 8 corners and the apex
  EXPECT_EQ(cells[1], 12u + 8);  // the cube's edges and one per corner to the apex
  EXPECT_EQ(cells[2], 6u + 12);  // the cube's faces and one triangle per edge
  EXPECT_EQ(cells[3], 6u);       // one pyramid per face
  const Pattern p = make_pattern("cube-cone", cone);
  EXPECT_EQ(p.boundary.size(), cube.map.size());
  EXPECT_EQ(p.map.flagged(), cube.map.size());
  EXPECT_FALSE(p.positive.empty());
  // Its boundary is the cube's: the store key of the pattern is the cell's, in both modes.
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    PatternStore s(mode);
    s.add(p);
    FlaggedMap target = testing::all_flagged(lift(make_cube(2), 3));
    EXPECT_EQ(query_replace(target, s, 3, [&] { ASSERT_TRUE(is_valid(target.map)); }).replaced(),
              1u);
    EXPECT_EQ(count_cells(target.map, 3), 6u);
  }
  // With positions, the apex is the mean of the corners (here every vertex is one).
  FlaggedMap unit = testing::all_flagged(make_cube(2));
  unit.position.resize(unit.map.capacity());
  for (Dart v : orbit_representatives(unit.map, cell_type(unit.map, 0))) {
    const double x = double(v % 2), y = double(v / 2 % 2), z = double(v / 4 % 2);
    for (Dart d : orbit(unit.map, cell_type(unit.map, 0), v)) unit.position[d] = {x, y, z};
  }
  const FlaggedMap positioned = cone_of_surface(unit);
  Vec3 mean{0, 0, 0};
  for (Dart v : orbit_representatives(unit.map, cell_type(unit.map, 0)))
    for (int k = 0; k < 3; ++k) mean[k] += unit.position[v][k] / 8;
  EXPECT_EQ(positioned.position[3 * unit.map.size()], mean);
  // Not a closed surface.
  FlaggedMap open = testing::all_flagged(make_grid(1, 1));
  EXPECT_THROW(cone_of_surface(open), Error);
}

// The conformal volume patterns: 325 in oriented mode, one per class, covering the 6209
// configurations without duplicates; the same set in unoriented mode covers the 226 classes, the
// 99 chiral pairs reported as duplicates; generated in unoriented mode, 226 patterns.
TEST(ConePattern, ConformalVolumePatternsCoverHexConformal) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  const std::vector<Pattern> oriented = conformal_volume_patterns(Mode::Oriented);
  ASSERT_EQ(oriented.size(), 325u);
  PatternStore os(Mode::Oriented), us(Mode::Unoriented);
  for (const Pattern& p : oriented) {
    os.add(p);
    us.add(p);
  }
  const CoverageReport o = check_coverage(os, set);
  EXPECT_EQ(o.classes, 325u);
  EXPECT_TRUE(o.complete());
  EXPECT_TRUE(os.duplicates().empty());
  const CoverageReport u = check_coverage(us, set);
  EXPECT_EQ(u.classes, 226u);
  EXPECT_TRUE(u.complete());
  EXPECT_EQ(us.duplicates().size(), 99u);
  for (const auto& group : us.duplicates()) EXPECT_EQ(group.size(), 2u);
  EXPECT_EQ(conformal_volume_patterns(Mode::Unoriented).size(), 226u);
}

// Conformal refinement of a hexahedron whose edges are split and one face cut: the volume matches
// its pattern and becomes one pyramid per boundary face, valid after the replacement.
TEST(ConePattern, RefinesAHexahedronWithSplitEdgesAndACutFace) {
  PatternStore store(Mode::Oriented);
  for (Pattern& p : conformal_volume_patterns(Mode::Oriented)) store.add(std::move(p));
  store.add(testing::pattern_file("conformal-faces", "split4"));
  FlaggedMap m = testing::all_flagged(lift(make_cube(2), 3));
  // Split the 4 edges of the face of dart 0 and 1 more edge, then cut that face into 4.
  std::vector<Dart> edges;
  Dart d = 0;
  do {
    edges.push_back(d);
    d = m.map.alpha(1, m.map.alpha(0, d));
  } while (d != 0);
  edges.push_back(
      m.map.alpha(1, m.map.alpha(2, 0)));  // an edge from the face's corner, off the face
  split_edges(m, edges, 2);
  const std::vector<Dart> face{0};
  EXPECT_EQ(query_replace(m, store, 2, {}, {}, {}, &face).replaced(), 1u);
  const size_t faces = count_cells(m.map, 2);
  const QueryReplaceReport v = query_replace(m, store, 3, [&] { ASSERT_TRUE(is_valid(m.map)); });
  EXPECT_EQ(v.replaced(), 1u);
  EXPECT_TRUE(v.unmatched.empty());
  EXPECT_EQ(count_cells(m.map, 3), faces);  // one pyramid per boundary face
}

// The generated patterns carry the unit cube's geometry: applied to an affine image of the unit
// cube (edges split, a face cut, all positioned), the apex goes to the image of the centre.
TEST(ConePattern, ApexAtTheCentreOfAPositionedHexahedron) {
  PatternStore store(Mode::Unoriented);
  for (Pattern& p : conformal_volume_patterns(Mode::Unoriented)) store.add(std::move(p));
  store.add(testing::pattern_file("conformal-faces", "split4"));
  FlaggedMap m = testing::all_flagged(make_polycube({{0, 0, 0}}));
  m.position = unit_hex_positions(m.map);
  // An affine map x -> A x + t.
  auto affine = [](const Vec3& p) {
    return Vec3{2 * p[0] + 0.5 * p[1] + 1, 3 * p[1] - 0.25 * p[2] - 2, 1.5 * p[2] + 0.5 * p[0] + 4};
  };
  for (Vec3& p : m.position) p = affine(p);
  split_edges(m, orbit_representatives(m.map, cell_type(m.map, 1)), 2);
  const std::vector<Dart> face{0};
  EXPECT_EQ(query_replace(m, store, 2, {}, {}, {}, &face).replaced(), 1u);
  const Dart first_new = m.map.capacity();
  const size_t boundary = orbit(m.map, cell_type(m.map, 3), 0).size();
  const QueryReplaceReport v = query_replace(m, store, 3);
  ASSERT_EQ(v.replaced(), 1u);
  const Vec3 centre = affine({0.5, 0.5, 0.5});
  size_t at_apex = 0;
  for (Dart d = first_new; d < m.map.capacity(); ++d) {
    const Vec3& p = m.position[d];
    if (std::abs(p[0] - centre[0]) + std::abs(p[1] - centre[1]) + std::abs(p[2] - centre[2]) < 1e-9)
      ++at_apex;
  }
  EXPECT_EQ(at_apex, boundary);  // t2(d) for every boundary dart d
  EXPECT_TRUE(is_valid(m.map));
}

}  // namespace
}  // namespace gmr::replace
