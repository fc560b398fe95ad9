// v-patterns and volume replacement (Damiand & Nivoliers 2022 §4.3, §5.1.2 read for G-maps: only
// alpha_2 is relinked), with the applications of §7.1 (hexahedral subdivision, Alg. 5) and §7.4
// (tetrahedra to hexahedra, Fig. 16); validity asserted after every replacement.
#include <gtest/gtest.h>

#include "model/core/validity.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

using testing::split_each_edge;

PatternStore folder_store(const std::string& set, Mode mode) {
  PatternStore s(mode);
  for (auto& p : load_patterns(testing::patterns_dir(set))) s.add(std::move(p));
  return s;
}

// Every dart flagged: the new cells' corners become the next level's (docs/query-replace.md,
// Flags).
void flag_all(FlaggedMap& m) { m.flag.assign(m.map.capacity(), 1); }

// e-pattern (split in 2), then faces, then volumes; validity after every replacement.
std::pair<QueryReplaceReport, QueryReplaceReport> refine(FlaggedMap& m, const PatternStore& store) {
  split_each_edge(m, 2);
  auto check = [&] { ASSERT_TRUE(is_valid(m.map)); };
  QueryReplaceReport f = query_replace(m, store, 2, check);
  QueryReplaceReport v = query_replace(m, store, 3, check);
  return {f, v};
}

// Every volume is a combinatorial hexahedron: its unflagged boundary signature is the cube's.
void expect_all_hexahedra(const Map& g) {
  const Word cube =
      minimal_signature(cell_boundary(make_cube(2), 3, 0, {}, {}), Mode::Unoriented, false).word;
  for (Dart v : orbit_representatives(g, cell_type(g, 3)))
    ASSERT_EQ(minimal_signature(cell_boundary(g, 3, v, {}, {}), Mode::Unoriented, false).word, cube)
        << "volume of dart " << v;
}

TEST(VolumePatterns, BoundaryAutomorphismsOfTheHexAndTetPatterns) {
  const Pattern hex = testing::pattern_file("hex-subdivision", "hex8");
  const Pattern tet = testing::pattern_file("tet-to-hex", "tet4");
  EXPECT_EQ(hex.map.map.size(), 384u);
  EXPECT_EQ(hex.boundary.size(), 192u);
  EXPECT_EQ(hex.map.flagged(), 48u);
  EXPECT_EQ(tet.map.map.size(), 192u);
  EXPECT_EQ(tet.boundary.size(), 96u);
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    PatternStore s(mode);
    s.add(hex);
    s.add(tet);
    const uint32_t k = mode == Mode::Oriented ? 1 : 2;
    EXPECT_EQ(s.entry(0).automorphisms, 24 * k);
    EXPECT_EQ(s.entry(1).automorphisms, 12 * k);
  }
}

TEST(VolumeReplacement, TetrahedronToFourHexahedra) {
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    FlaggedMap m{lift(make_tetrahedron(2), 3), {}, {}};
    flag_all(m);
    const auto c = count_all_cells(m.map);
    const auto [f, v] = refine(m, folder_store("tet-to-hex", mode));
    EXPECT_EQ(f.replaced(), c[2]);
    EXPECT_EQ(v.replaced(), c[3]);
    EXPECT_TRUE(v.unmatched.empty());
    const auto a = count_all_cells(m.map);
    EXPECT_EQ(a[0], c[0] + c[1] + c[2] + c[3]);  // V' = V + E + F + T
    EXPECT_EQ(a[3], 4 * c[3]);                   // #hex = 4 #tet
    EXPECT_EQ(euler_characteristic(m.map), euler_characteristic(lift(make_tetrahedron(2), 3)));
    expect_all_hexahedra(m.map);
  }
}

// Alg. 5 without the geometric selection: every hexahedron of a polycube refined, two levels.
TEST(VolumeReplacement, HexahedralSubdivisionOfAPolycubeOverTwoLevels) {
  const std::vector<Voxel> voxels{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};
  FlaggedMap m{make_polycube(voxels), {}, {}};
  const PatternStore store = folder_store("hex-subdivision", Mode::Unoriented);
  const long long euler = euler_characteristic(m.map);
  size_t volumes = voxels.size();
  for (int level = 1; level <= 2; ++level) {
    flag_all(m);
    const auto c = count_all_cells(m.map);
    const auto [f, v] = refine(m, store);
    EXPECT_EQ(f.replaced(), c[2]) << level;
    EXPECT_EQ(v.replaced(), volumes) << level;
    EXPECT_TRUE(f.unmatched.empty() && v.unmatched.empty());
    volumes *= 8;
    const auto a = count_all_cells(m.map);
    EXPECT_EQ(a[3], volumes);
    EXPECT_EQ(a[0], c[0] + c[1] + c[2] + c[3]);  // corners, edge, face and cell centres
    EXPECT_EQ(euler_characteristic(m.map), euler);
  }
  expect_all_hexahedra(m.map);
}

// Without flags on the target, the flagged v-pattern matches nothing: volumes are reported.
TEST(VolumeReplacement, UnflaggedVolumesAreLeftUntouched) {
  FlaggedMap m{lift(make_cube(2), 3), {}, {}};
  flag_all(m);
  split_each_edge(m, 2);
  const PatternStore store = folder_store("hex-subdivision", Mode::Unoriented);
  query_replace(m, store, 2);
  m.flag.assign(m.map.capacity(), 0);
  const size_t darts = m.map.size();
  const QueryReplaceReport v = query_replace(m, store, 3);
  EXPECT_EQ(v.replaced(), 0u);
  EXPECT_EQ(v.unmatched.size(), 1u);
  EXPECT_EQ(m.map.size(), darts);
}

}  // namespace
}  // namespace gmr::replace
