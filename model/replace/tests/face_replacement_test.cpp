// e-patterns, f-patterns and face replacement (Damiand & Nivoliers 2022 §4.1, §4.2, §5.1.1 read
// for G-maps), with validity asserted after every replacement.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

using testing::all_flagged;
using testing::pattern_file;
using testing::split_each_edge;

PatternStore store_of(Mode mode, std::vector<Pattern> ps) {
  PatternStore s(mode);
  for (auto& p : ps) s.add(std::move(p));
  return s;
}

// Subdivides every face of a flagged polyhedron: edges split in 2, faces by `pattern`, validity
// checked after each replacement; returns the report.
QueryReplaceReport subdivide(FlaggedMap& m, const Pattern& pattern, Mode mode = Mode::Unoriented) {
  split_each_edge(m, 2);
  EXPECT_TRUE(is_valid(m.map));
  const PatternStore store = store_of(mode, {pattern});
  return query_replace(m, store, 2, [&] { ASSERT_TRUE(is_valid(m.map)); });
}

TEST(EdgeSplit, SplitsEveryDartPairAndKeepsFlagsOnOldDarts) {
  for (unsigned k : {2u, 3u, 5u}) {
    FlaggedMap m = all_flagged(make_stacked_cubes());
    const auto before = count_all_cells(m.map);
    const size_t darts = m.map.size();
    // The edge of dart 0 is shared by the two cubes or not; either way its orbit is split.
    const size_t orbit_size = orbit(m.map, cell_type(m.map, 1), 0).size();
    EXPECT_EQ(split_edge(m, 0, k), orbit_size * (k - 1));
    EXPECT_TRUE(is_valid(m.map)) << k;
    const auto after = count_all_cells(m.map);
    EXPECT_EQ(after[0], before[0] + (k - 1));
    EXPECT_EQ(after[1], before[1] + (k - 1));
    EXPECT_EQ(after[2], before[2]);
    EXPECT_EQ(m.map.size(), darts + orbit_size * (k - 1));
    EXPECT_EQ(m.flagged(), darts);  // new darts are unflagged
  }
}

// split_all_edges (every dart pair at once, no edge traversal) is split_edge on every edge in
// turn, up to the numbering of the new darts: isomorphic, same flags and positions; on a map with
// holes too.
TEST(EdgeSplit, SplitAllEdgesEqualsSplittingEveryEdge) {
  for (unsigned k : {2u, 3u}) {
    FlaggedMap a = all_flagged(make_stacked_cubes());
    a.position.resize(a.map.capacity());
    for (Dart v : orbit_representatives(a.map, cell_type(a.map, 0)))
      for (Dart x : orbit(a.map, cell_type(a.map, 0), v))
        a.position[x] = {double(v % 7), double(v % 5), double(v % 3)};
    FlaggedMap b = a;
    const size_t before = a.map.size();
    split_each_edge(a, k);
    EXPECT_EQ(split_all_edges(b, k), a.map.size() - before);
    EXPECT_TRUE(is_valid(b.map));
    EXPECT_EQ(b.flagged(), a.flagged());
    EXPECT_TRUE(is_isomorphic(a.map, b.map, &a.flag, &b.flag)) << k;
    // The new vertices are interpolated from either end of their edge: equal up to rounding.
    EXPECT_EQ(testing::position_multiset(a, 1e9), testing::position_multiset(b, 1e9));
  }
  FlaggedMap holes = all_flagged(make_stacked_cubes());
  holes.map.remove_dart(holes.map.add_dart());  // a deleted dart in the index range
  holes.resize_flags();
  FlaggedMap each = holes;
  split_each_edge(each, 2);
  split_all_edges(holes, 2);
  EXPECT_TRUE(is_isomorphic(each.map, holes.map, &each.flag, &holes.flag));
  EXPECT_EQ(split_all_edges(holes, 1), 0u);
  EXPECT_THROW(split_all_edges(holes, 0), Error);
}

// split_edges on a list of edges is split_edge on each in turn, up to the numbering of the new
// darts: the same map up to isomorphism, with the same flags and positions; a map with holes and
// a positioned polycube; an edge named twice and a 0-free dart are refused.
TEST(EdgeSplit, SplitEdgesEqualsSplittingOneEdgeAfterTheOther) {
  for (unsigned k : {2u, 3u}) {
    FlaggedMap one = all_flagged(make_stacked_cubes());
    // Every other edge, so that split and unsplit edges meet.
    std::vector<Dart> edges = orbit_representatives(one.map, cell_type(one.map, 1));
    std::erase_if(edges, [&](Dart e) { return e % 3 == 0; });
    FlaggedMap all = one;
    size_t added = 0;
    for (Dart e : edges) added += split_edge(one, e, k);
    EXPECT_EQ(split_edges(all, edges, k), added);
    EXPECT_TRUE(is_valid(all.map));
    EXPECT_EQ(all.map.size(), one.map.size());
    EXPECT_EQ(all.flagged(), one.flagged());
    EXPECT_TRUE(is_isomorphic(one.map, all.map, &one.flag, &all.flag)) << k;
  }
  // Positions: the new vertices at the same places.
  FlaggedMap cube{lift(make_cube(2), 3), {}, {}};
  cube.flag.assign(cube.map.capacity(), 1);
  cube.position.resize(cube.map.capacity());
  cube.map.for_each_dart([&](Dart d) {
    cube.position[d] = {double(d % 7), double(d % 5), double(d % 3)};
  });
  // A vertex position per vertex orbit (its smallest dart's made up position).
  for (Dart v : orbit_representatives(cube.map, cell_type(cube.map, 0)))
    for (Dart x : orbit(cube.map, cell_type(cube.map, 0), v)) cube.position[x] = cube.position[v];
  FlaggedMap a = cube, b = cube;
  for (Dart e : orbit_representatives(a.map, cell_type(a.map, 1))) split_edge(a, e, 3);
  split_edges(b, orbit_representatives(b.map, cell_type(b.map, 1)), 3);
  auto points = [](const FlaggedMap& m) {
    std::vector<Vec3> p;
    m.map.for_each_dart([&](Dart d) { p.push_back(m.position[d]); });
    std::sort(p.begin(), p.end());
    return p;
  };
  EXPECT_EQ(points(a), points(b));
  EXPECT_TRUE(is_isomorphic(a.map, b.map));
  // An edge named twice (two darts of one edge), a 0-free dart.
  FlaggedMap twice = all_flagged(make_cube(2));
  EXPECT_THROW(split_edges(twice, {0, twice.map.alpha(0, 0)}, 2), Error);
  EXPECT_THROW(split_edges(twice, {0}, 3000000000u), Error);  // more darts than can be numbered
  EXPECT_EQ(twice.map.size(), 48u);
  FlaggedMap open{Map(2), {}, {}};
  open.map.add_darts(2);
  open.map.link(1, 0, 1);
  open.resize_flags();
  EXPECT_THROW(split_edges(open, {0}, 2), Error);
}

TEST(FaceReplacement, SquareWithSplitEdgesBecomesFourQuads) {
  const Pattern p = pattern_file("conformal-faces", "split4");
  EXPECT_EQ(p.map.map.size(), 32u);
  EXPECT_EQ(p.boundary.size(), 16u);
  EXPECT_EQ(p.interior, 16u);
  FlaggedMap m = all_flagged(make_polygon(4));
  const QueryReplaceReport r = subdivide(m, p);
  EXPECT_EQ(r.cells, 1u);
  EXPECT_EQ(r.replaced(), 1u);
  EXPECT_TRUE(r.unmatched.empty());
  EXPECT_EQ(count_cells(m.map, 2), 4u);
  EXPECT_EQ(count_cells(m.map, 0), 9u);
  for (Dart f : orbit_representatives(m.map, cell_type(m.map, 2)))
    EXPECT_EQ(orbit(m.map, OrbitType{0, 1}, f).size(), 8u);  // quads
}

// The cube's faces cut in 4: the boundary of the Fig. 9b pattern (192 darts, 48 flagged), and the
// tetrahedron's faces cut in 3 quads (96 darts).
TEST(FaceReplacement, CubeAndTetrahedronBoundaries) {
  struct Case {
    Map polyhedron;
    const char* pattern;
    size_t darts, flagged;
    uint32_t aut_oriented, aut_unoriented;
  };
  // Expected sizes: every face of k sides becomes k quads (8 darts each); the flagged darts are the
  // original darts' halves that kept their vertex: 2 per corner of each face.
  std::vector<Case> cases;
  cases.push_back({make_cube(2), "split4", 6 * 4 * 8, 6 * 4 * 2, 24, 48});
  cases.push_back({make_tetrahedron(2), "triangle3", 4 * 3 * 8, 4 * 3 * 2, 12, 24});
  for (auto& c : cases) {
    const auto cells = count_all_cells(c.polyhedron);
    FlaggedMap m = all_flagged(std::move(c.polyhedron));
    const Pattern p = pattern_file(
        std::string(c.pattern) == "split4" ? "conformal-faces" : "tet-to-hex", c.pattern);
    const QueryReplaceReport r = subdivide(m, p);
    EXPECT_EQ(r.replaced(), cells[2]) << c.pattern;
    EXPECT_EQ(m.map.size(), c.darts);
    EXPECT_EQ(m.flagged(), c.flagged);
    const auto after = count_all_cells(m.map);
    EXPECT_EQ(after[0], cells[0] + cells[1] + cells[2]);  // corners, edge midpoints, face centres
    const BoundaryGraph b = cell_boundary(m.map, 3, 0, m.flag, orientation_classes(m.map));
    const CellSignature o = minimal_signature(b, Mode::Oriented),
                        u = minimal_signature(b, Mode::Unoriented);
    EXPECT_EQ(o.automorphisms, c.aut_oriented) << c.pattern;
    EXPECT_EQ(u.automorphisms, c.aut_unoriented) << c.pattern;
    EXPECT_EQ(u.word.size(), 4 * c.darts);
  }
}

// A face shared by two volumes is replaced on both half-faces (mirror copy, alpha_3-linked).
TEST(FaceReplacement, SharedFacesOfStackedCubes) {
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    FlaggedMap m = all_flagged(make_stacked_cubes());
    const auto c = count_all_cells(m.map);
    const QueryReplaceReport r = subdivide(m, pattern_file("conformal-faces", "split4"), mode);
    EXPECT_EQ(r.replaced(), c[2]);
    EXPECT_TRUE(r.unmatched.empty());
    const auto a = count_all_cells(m.map);
    EXPECT_EQ(a[0], c[0] + c[1] + c[2]);
    EXPECT_EQ(a[1], 2 * c[1] + 4 * c[2]);
    EXPECT_EQ(a[2], 4 * c[2]);
    EXPECT_EQ(a[3], c[3]);
    EXPECT_EQ(euler_characteristic(m.map), euler_characteristic(make_stacked_cubes()));
    // Each volume is now the cube boundary cut in 4: 192 darts.
    for (Dart v : orbit_representatives(m.map, cell_type(m.map, 3)))
      EXPECT_EQ(orbit(m.map, OrbitType{0, 1, 2}, v).size(), 192u);
  }
}

// Copied darts take the pattern dart's flag: the inner darts of the patterns are unflagged, so
// the flagged darts after replacement are exactly the target's.
TEST(FaceReplacement, FlagsOfCopiedDartsComeFromThePattern) {
  const Pattern p = pattern_file("conformal-faces", "split4");
  size_t inner_flagged = 0;
  p.map.map.for_each_dart(
      [&](Dart d) { inner_flagged += !p.map.map.is_free(2, d) && p.map.flag[d]; });
  FlaggedMap m = all_flagged(make_cube(2));
  split_each_edge(m, 2);
  const size_t before = m.flagged();
  query_replace(m, store_of(Mode::Unoriented, {p}), 2);
  EXPECT_EQ(m.flagged(), before + 6 * inner_flagged);
}

// Faces matching no pattern are left untouched and reported.
TEST(FaceReplacement, UnmatchedFacesAreReportedAndKept) {
  FlaggedMap m = all_flagged(make_cube(2));
  split_edge(m, 0, 2);  // two faces now have one split edge; four have none
  const size_t darts = m.map.size();
  const PatternStore store =
      store_of(Mode::Unoriented, {pattern_file("conformal-faces", "split4")});
  const QueryReplaceReport r = query_replace(m, store, 2);
  EXPECT_EQ(r.cells, 6u);
  EXPECT_EQ(r.replaced(), 0u);
  EXPECT_EQ(r.unmatched.size(), 6u);
  EXPECT_EQ(m.map.size(), darts);
  // With the one-split-edge pattern, exactly the two faces of the split edge match.
  const PatternStore store1 =
      store_of(Mode::Unoriented, {pattern_file("conformal-faces", "split1")});
  const QueryReplaceReport r1 = query_replace(m, store1, 2, [&] { ASSERT_TRUE(is_valid(m.map)); });
  EXPECT_EQ(r1.replaced(), 2u);
  EXPECT_EQ(r1.unmatched.size(), 4u);
  EXPECT_EQ(count_cells(m.map, 2), 6u - 2 + 2 * 3);
}

// Every subset of split edges of a cube: the conformal set replaces exactly the faces with a split
// edge (each face's configuration is one of the 5 classes, applied through any automorphism or
// reflection), and the result stays valid after each replacement, in both modes.
TEST(FaceReplacement, ConformalSetOnEveryEdgeSubsetOfACube) {
  std::vector<Pattern> ps = load_patterns(testing::patterns_dir("conformal-faces"));
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    const PatternStore store = store_of(mode, ps);
    for (uint32_t mask = 1; mask < (1u << 12); mask += 37) {
      FlaggedMap m = all_flagged(make_cube(2));
      const std::vector<Dart> edges = orbit_representatives(m.map, cell_type(m.map, 1));
      for (size_t e = 0; e < edges.size(); ++e)
        if (mask >> e & 1) split_edge(m, edges[e], 2);
      size_t touched = 0;  // faces with a split edge: more than 8 darts
      for (Dart f : orbit_representatives(m.map, cell_type(m.map, 2)))
        touched += orbit(m.map, OrbitType{0, 1}, f).size() > 8;
      const QueryReplaceReport r =
          query_replace(m, store, 2, [&] { ASSERT_TRUE(is_valid(m.map)); });
      EXPECT_EQ(r.replaced(), touched) << mask;
      EXPECT_EQ(r.unmatched.size(), 6 - touched) << mask;
      EXPECT_EQ(euler_characteristic(m.map), 2);
    }
  }
}

// An open surface (2-free darts on its border) and a map with deleted darts.
TEST(FaceReplacement, OpenGridAndMapWithHoles) {
  FlaggedMap m = all_flagged(make_grid(2, 2));
  split_each_edge(m, 2);
  const PatternStore store =
      store_of(Mode::Unoriented, {pattern_file("conformal-faces", "split4")});
  EXPECT_EQ(query_replace(m, store, 2, [&] { ASSERT_TRUE(is_valid(m.map)); }).replaced(), 4u);
  EXPECT_EQ(count_cells(m.map, 2), 16u);
  // Deleted darts leave holes in the index range: build a square after a deleted component.
  Map g(2);
  const Dart junk = g.add_dart();
  Map sq = make_polygon(4);
  const Dart base = g.add_darts(sq.size());
  sq.for_each_dart([&](Dart x) {
    for (int i = 0; i <= 2; ++i) g.set_alpha(i, base + x, base + sq.alpha(i, x));
  });
  g.remove_dart(junk);
  FlaggedMap h = all_flagged(std::move(g));
  split_each_edge(h, 2);
  EXPECT_EQ(query_replace(h, store, 2, [&] { ASSERT_TRUE(is_valid(h.map)); }).replaced(), 1u);
  EXPECT_EQ(count_cells(h.map, 2), 4u);
}

TEST(FaceReplacement, RefusesInvalidTargetsAndWrongDimensions) {
  FlaggedMap m = all_flagged(make_cube(2));
  m.map.set_alpha(0, 0, 5);  // breaks the involution
  const PatternStore store =
      store_of(Mode::Unoriented, {pattern_file("conformal-faces", "split4")});
  EXPECT_THROW(query_replace(m, store, 2), Error);
  FlaggedMap one{Map(1), {}, {}};
  EXPECT_THROW(query_replace(one, store, 2), Error);
  // A cell listed twice (two darts of one face, on its two half-faces) is refused, the map kept.
  FlaggedMap cubes = all_flagged(make_stacked_cubes());
  split_each_edge(cubes, 2);
  Dart shared = kNoDart;
  cubes.map.for_each_dart([&](Dart d) {
    if (shared == kNoDart && !cubes.map.is_free(3, d)) shared = d;
  });
  ASSERT_NE(shared, kNoDart);
  const std::vector<Dart> twice{shared, cubes.map.alpha(3, shared)};
  const size_t darts = cubes.map.size();
  EXPECT_THROW(query_replace(cubes, store, 2, {}, {}, {}, &twice), Error);
  EXPECT_EQ(cubes.map.size(), darts);
}

}  // namespace
}  // namespace gmr::replace

namespace gmr::replace {
namespace {

// A second f-pattern with split4's boundary (a square with split edges) and another interior: two
// pentagons cut along the segment joining two opposite midpoints. Corners 0..3, midpoints 4..7.
Pattern two_pentagons() {
  std::vector<uint32_t> vertex;
  FlaggedMap m{surface_from_faces({{0, 4, 6, 3, 7}, {4, 1, 5, 2, 6}}, 8, {}, &vertex), {}, {}};
  m.flag.assign(m.map.capacity(), 0);
  // Flagged: boundary darts at a corner (their edge goes to a midpoint, on an original edge).
  m.map.for_each_dart([&](Dart d) { m.flag[d] = m.map.is_free(2, d) && vertex[d] < 4 ? 1 : 0; });
  return make_pattern("two-pentagons", std::move(m));
}

// §6.4: patterns with isomorphic boundaries are duplicates; query-replace takes the first one
// unless a selector chooses; an out-of-range choice is refused.
TEST(FaceReplacement, DuplicateSelectorChoosesAmongPatternsOfOneKey) {
  PatternStore store(Mode::Unoriented);
  store.add(pattern_file("conformal-faces", "split4"));
  store.add(two_pentagons());
  ASSERT_EQ(store.duplicates(), (std::vector<std::vector<size_t>>{{0, 1}}));
  auto run = [&](const DuplicateSelector& select) {
    FlaggedMap m = all_flagged(make_cube(2));
    split_each_edge(m, 2);
    const QueryReplaceReport r = query_replace(
        m, store, 2, [&] { ASSERT_TRUE(is_valid(m.map)); }, {}, select);
    EXPECT_EQ(r.ambiguous_keys, 6u);
    return std::make_pair(r, count_cells(m.map, 2));
  };
  const auto [first, faces_first] = run({});
  EXPECT_EQ(first.matched, (std::vector<size_t>{6, 0}));
  EXPECT_EQ(faces_first, 24u);
  // Every other face (by the parity of its dart) gets the pentagons.
  const auto [chosen, faces_chosen] = run([](const std::vector<StoreEntry>& c, const FlaggedMap&,
                                             Dart d) { return c.size() - 1 - (d % 2); });
  EXPECT_EQ(chosen.matched[0] + chosen.matched[1], 6u);
  EXPECT_GT(chosen.matched[1], 0u);
  EXPECT_EQ(faces_chosen, 4 * chosen.matched[0] + 2 * chosen.matched[1]);
  EXPECT_THROW(
      run([](const std::vector<StoreEntry>& c, const FlaggedMap&, Dart) { return c.size(); }),
      Error);
}

}  // namespace
}  // namespace gmr::replace
