// Replace only (§7.1, Table 1's "only the replace part"): the hexahedral subdivision with every
// cell known to match its pattern, no query. The cell's boundary is traversed from the dart given
// as matched with the pattern's start and checked against the pattern's word; the replacement is
// query-replace's.
#include "model/replace/replace_only.hpp"

#include <gtest/gtest.h>

#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/replace/direct_hex_subdivision.hpp"
#include "model/replace/edge_split.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/replace/unit_hex_positions.hpp"

namespace gmr::replace {
namespace {

PatternStore hex_subdivision_patterns() {
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  return store;
}

size_t index_of_pattern(const PatternStore& store, const std::string& name) {
  for (size_t i = 0; i < store.patterns().size(); ++i)
    if (store.patterns()[i].name == name) return i;
  ADD_FAILURE() << "no pattern " << name;
  return 0;
}

bool same_darts(const FlaggedMap& a, const FlaggedMap& b) {
  if (a.map.capacity() != b.map.capacity() || a.flag != b.flag || a.position != b.position)
    return false;
  for (int i = 0; i <= 3; ++i)
    if (a.map.links(i) != b.map.links(i)) return false;
  return true;
}

const std::vector<Voxel> kSixVoxels{{0, 0, 0}, {1, 0, 0}, {2, 0, 0},
                                    {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};

// Every cell met at its smallest dart, a flagged corner dart: the boundary automorphisms of
// split4 and hex8 are transitive on their flagged darts, so that dart matches the start. Two
// levels: the same map, dart for dart, as query-replace (whose first start dart is that dart), the
// direct subdivision up to isomorphism, valid after every replacement.
TEST(ReplaceOnly, HexSubdivisionIsQueryReplaceDartForDart) {
  const PatternStore store = hex_subdivision_patterns();
  const size_t split4 = index_of_pattern(store, "split4"), hex8 = index_of_pattern(store, "hex8");
  FlaggedMap only = testing::positioned_polycube(kSixVoxels), qr = only, direct = only;
  for (int level = 1; level <= 2; ++level) {
    direct = subdivide_hexahedra(direct);
    split_all_edges(only, 2);
    split_all_edges(qr, 2);
    auto valid = [&] { ASSERT_TRUE(is_valid(only.map)); };
    const QueryReplaceReport f =
        replace_only(only, store, split4, nullptr, Precondition::CheckValidity, valid);
    const QueryReplaceReport v =
        replace_only(only, store, hex8, nullptr, Precondition::AssumeValid, valid);
    EXPECT_TRUE(f.unmatched.empty() && v.unmatched.empty());
    EXPECT_EQ(f.matched[split4], f.cells);
    EXPECT_EQ(v.matched[hex8], v.cells);
    EXPECT_EQ(v.cells, kSixVoxels.size() * (level == 1 ? 1 : 8));
    const QueryReplaceReport qf = query_replace(qr, store, 2), qv = query_replace(qr, store, 3);
    EXPECT_EQ(f.darts_added, qf.darts_added);
    EXPECT_EQ(v.darts_added, qv.darts_added);
    EXPECT_TRUE(same_darts(only, qr)) << level;
    EXPECT_TRUE(is_isomorphic(direct.map, only.map)) << level;
    only.flag.assign(only.map.capacity(), 1);
    qr.flag.assign(qr.map.capacity(), 1);
  }
}

// Listed cells, each from another flagged dart (the largest of its cell): every start of a
// transitive automorphism group gives an isomorphic result, valid after every replacement.
TEST(ReplaceOnly, ListedCellsFromOtherStartDarts) {
  const PatternStore store = hex_subdivision_patterns();
  const size_t split4 = index_of_pattern(store, "split4"), hex8 = index_of_pattern(store, "hex8");
  FlaggedMap listed = testing::positioned_polycube(kSixVoxels);
  const FlaggedMap direct = subdivide_hexahedra(listed);
  split_all_edges(listed, 2);
  auto largest_flagged = [&](int cell_dim) {
    std::vector<Dart> starts;
    for (Dart rep : orbit_representatives(listed.map, cell_type(listed.map, cell_dim))) {
      Dart best = rep;
      for (Dart x : orbit(listed.map, OrbitType::range(0, cell_dim - 1), rep))
        if (listed.flag[x] && x > best) best = x;
      starts.push_back(best);
    }
    return starts;
  };
  auto valid = [&] { ASSERT_TRUE(is_valid(listed.map)); };
  const std::vector<Dart> faces = largest_flagged(2);
  EXPECT_NE(faces, orbit_representatives(listed.map, cell_type(listed.map, 2)));
  const QueryReplaceReport f =
      replace_only(listed, store, split4, &faces, Precondition::CheckValidity, valid);
  const std::vector<Dart> volumes = largest_flagged(3);
  const QueryReplaceReport v =
      replace_only(listed, store, hex8, &volumes, Precondition::CheckValidity, valid);
  EXPECT_TRUE(f.unmatched.empty() && v.unmatched.empty());
  EXPECT_EQ(v.cells, kSixVoxels.size());
  EXPECT_TRUE(is_isomorphic(direct.map, listed.map));
}

// A cell that is not the pattern's boundary from the given dart is left untouched: faces whose
// edges are not split (8 darts, not split4's 16), and a split face given by an unflagged dart.
TEST(ReplaceOnly, CellNotMatchingFromItsDartIsLeftUntouched) {
  const PatternStore store = hex_subdivision_patterns();
  const size_t split4 = index_of_pattern(store, "split4");
  FlaggedMap m = testing::positioned_polycube({{0, 0, 0}, {1, 0, 0}});
  const FlaggedMap before = m;
  const QueryReplaceReport r = replace_only(m, store, split4);
  EXPECT_EQ(r.unmatched.size(), r.cells);
  EXPECT_EQ(r.replaced(), 0u);
  EXPECT_TRUE(same_darts(m, before));

  const size_t old_darts = m.map.size();
  split_all_edges(m, 2);
  const FlaggedMap split = m;
  // Dart old_darts is a new dart of a split edge: unflagged, its face's flagged corner darts are
  // the ones matched with split4's start.
  ASSERT_EQ(m.flag[old_darts], 0u);
  const std::vector<Dart> unflagged{static_cast<Dart>(old_darts)}, flagged{0};
  const QueryReplaceReport u = replace_only(m, store, split4, &unflagged);
  EXPECT_EQ(u.unmatched, unflagged);
  EXPECT_TRUE(same_darts(m, split));
  const QueryReplaceReport ok = replace_only(m, store, split4, &flagged);
  EXPECT_EQ(ok.replaced(), 1u);
  EXPECT_TRUE(is_valid(m.map));
}

TEST(ReplaceOnly, RefusesBadArgumentsBeforeAnyChange) {
  const PatternStore store = hex_subdivision_patterns();
  const size_t split4 = index_of_pattern(store, "split4"), hex8 = index_of_pattern(store, "hex8");
  FlaggedMap m = testing::positioned_polycube({{0, 0, 0}, {1, 0, 0}});
  split_all_edges(m, 2);
  const FlaggedMap before = m;
  EXPECT_THROW(replace_only(m, store, store.patterns().size()), Error);
  // Darts 0 and alpha_0 alpha_1 alpha_0 (0)... of one face: the same cell listed twice.
  const Dart other = m.map.alpha(1, m.map.alpha(0, 0));
  const std::vector<Dart> twice{0, other}, dead{static_cast<Dart>(m.map.capacity() + 5)};
  EXPECT_THROW(replace_only(m, store, split4, &twice), Error);
  EXPECT_THROW(replace_only(m, store, split4, &dead), Error);
  EXPECT_TRUE(same_darts(m, before));
  FlaggedMap surface{make_cube(2), {}, {}};
  EXPECT_THROW(replace_only(surface, store, hex8), Error);  // volumes of a 2-G-map
  FlaggedMap broken = before;
  broken.map.set_alpha(3, 0, 1);  // not an involution
  EXPECT_THROW(replace_only(broken, store, split4), Error);
}

}  // namespace
}  // namespace gmr::replace
