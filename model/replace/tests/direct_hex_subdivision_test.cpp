// The direct hexahedral subdivision (§7.1's "time-direct") against query-replace with the
// hex-subdivision patterns: the same map up to isomorphism and the same vertex positions.
#include "model/replace/direct_hex_subdivision.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/replace/edge_split.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/replace/unit_hex_positions.hpp"

namespace gmr::replace {
namespace {

using testing::position_multiset;

TEST(DirectHexSubdivision, UnitPositionsOfAPolycube) {
  const FlaggedMap m = testing::positioned_polycube({{0, 0, 0}, {1, 0, 0}});
  // 12 vertices at integer points; every dart of a vertex at the same place.
  std::vector<std::array<long long, 3>> points = position_multiset(m);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  EXPECT_EQ(points.size(), 12u);
}

TEST(DirectHexSubdivision, SameMapAndPositionsAsQueryReplace) {
  const std::vector<Voxel> voxels{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};
  const FlaggedMap input = testing::positioned_polycube(voxels);
  FlaggedMap direct = subdivide_hexahedra(input);
  EXPECT_TRUE(is_valid(direct.map));
  EXPECT_EQ(direct.map.size(), 8 * input.map.size());

  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  FlaggedMap qr = input;
  testing::split_each_edge(qr, 2);
  EXPECT_TRUE(query_replace(qr, store, 2).unmatched.empty());
  EXPECT_TRUE(query_replace(qr, store, 3).unmatched.empty());

  EXPECT_TRUE(is_isomorphic(direct.map, qr.map));
  EXPECT_EQ(position_multiset(direct), position_multiset(qr));
  // A second level of each stays the same.
  FlaggedMap direct2 = subdivide_hexahedra(direct);
  qr.flag.assign(qr.map.capacity(), 1);
  testing::split_each_edge(qr, 2);
  query_replace(qr, store, 2);
  query_replace(qr, store, 3);
  EXPECT_EQ(count_all_cells(direct2.map)[3], 64 * voxels.size());
  EXPECT_TRUE(is_isomorphic(direct2.map, qr.map));
  EXPECT_EQ(position_multiset(direct2), position_multiset(qr));
}

// The sequence as the benchmark runs it: its final size reserved from replacement_room before
// any step (faces and volumes counted in one sweep, as the two counts give it) (no array grows: the
// link arrays stay in place), every edge split at once (split_edges on the edges, or
// split_all_edges), then faces and volumes (validity checked by query_replace, or assumed as the
// benchmark's AssumeValid variant does); the bound is exact for hexahedra (so is the bound from the
// dart count), and the result is the direct subdivision up to isomorphism, with the same positions,
// valid after every replacement.
TEST(DirectHexSubdivision, ReservedSequenceEqualsTheDirectSubdivision) {
  const std::vector<Voxel> voxels{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  for (Precondition pre : {Precondition::CheckValidity, Precondition::AssumeValid}) {
    FlaggedMap qr = testing::positioned_polycube(voxels);
    FlaggedMap direct = testing::positioned_polycube(voxels);
    for (int level = 1; level <= 2; ++level) {
      direct = subdivide_hexahedra(direct);
      const size_t darts = qr.map.size();
      const size_t faces = replacement_room(qr.map, store, 2),
                   volumes = replacement_room(qr.map, store, 3);
      EXPECT_EQ(replacement_room(qr.map, store, {2, 3}), faces + volumes);  // one sweep for both
      EXPECT_EQ(replacement_room_bound(2 * darts, store, {2, 3}),
                faces + volumes);  // from the darts alone
      qr.reserve(2 * darts + replacement_room(qr.map, store, {2, 3}));
      const Dart* links = qr.map.links(0).data();
      if (pre == Precondition::CheckValidity)
        EXPECT_EQ(split_edges(qr, orbit_representatives(qr.map, cell_type(qr.map, 1)), 2), darts);
      else
        EXPECT_EQ(split_all_edges(qr, 2), darts);
      auto valid = [&] { ASSERT_TRUE(is_valid(qr.map)); };
      const QueryReplaceReport f = query_replace(qr, store, 2, valid, {}, {}, nullptr, pre);
      const QueryReplaceReport v = query_replace(qr, store, 3, valid, {}, {}, nullptr, pre);
      EXPECT_TRUE(f.unmatched.empty() && v.unmatched.empty());
      EXPECT_EQ(f.darts_added, faces);
      EXPECT_EQ(v.darts_added, volumes);
      EXPECT_EQ(qr.map.links(0).data(), links) << "an array grew beyond the reserved size";
      EXPECT_EQ(qr.map.size(), direct.map.size());
      EXPECT_TRUE(is_isomorphic(direct.map, qr.map)) << level;
      EXPECT_EQ(position_multiset(direct), position_multiset(qr)) << level;
      qr.flag.assign(qr.map.capacity(), 1);
    }
  }
}

// An invalid map is refused by the check and not when the caller assumes it valid.
TEST(DirectHexSubdivision, ValidityIsCheckedUnlessAssumed) {
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  FlaggedMap broken = testing::positioned_polycube({{0, 0, 0}});
  broken.map.set_alpha(3, 0, 1);  // one direction only: not an involution
  EXPECT_THROW(query_replace(broken, store, 2), Error);
  EXPECT_NO_THROW(query_replace(broken, store, 2, {}, {}, {}, nullptr, Precondition::AssumeValid));
}

TEST(DirectHexSubdivision, RejectsNonHexahedra) {
  FlaggedMap tet{lift(make_tetrahedron(2), 3), {}, {}};
  EXPECT_THROW(subdivide_hexahedra(tet), Error);
  FlaggedMap surface{make_cube(2), {}, {}};
  EXPECT_THROW(subdivide_hexahedra(surface), Error);
}

}  // namespace
}  // namespace gmr::replace
