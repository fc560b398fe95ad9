// Dart storage: deletion with reuse, markers, memory, links.
#include <gtest/gtest.h>

#include <algorithm>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"

using namespace gmr;

TEST(Map, RemoveAndReuseDarts) {
  Map g = make_polygon(3, 2);
  const Dart d = 2, p0 = g.alpha(0, d), p1 = g.alpha(1, d);
  g.remove_dart(d);
  EXPECT_FALSE(g.alive(d));
  EXPECT_EQ(g.size(), 5u);
  EXPECT_TRUE(g.is_free(0, p0));
  EXPECT_TRUE(g.is_free(1, p1));
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(g.darts().size(), 5u);
  const Dart r = g.add_dart();
  EXPECT_EQ(r, d);  // reused
  EXPECT_TRUE(g.is_free(0, r));
  EXPECT_EQ(g.capacity(), 6u);
  EXPECT_THROW(g.remove_dart(100), Error);
}

TEST(Map, OMapRemoveFixesPredecessor) {
  Map o = orient(make_cube(2));
  const Dart d = 0;
  Dart pred = d;
  while (o.alpha(1, pred) != d) pred = o.alpha(1, pred);
  o.remove_dart(d);
  EXPECT_TRUE(o.is_free(1, pred));
}

TEST(Map, MarkersAreReusable) {
  Map g = make_cube(2);
  const int m1 = g.reserve_marker();
  const int m2 = g.reserve_marker();
  EXPECT_NE(m1, m2);
  g.mark(3, m1);
  EXPECT_TRUE(g.is_marked(3, m1));
  EXPECT_FALSE(g.is_marked(3, m2));
  g.unmark(3, m1);
  g.release_marker(m1);
  EXPECT_EQ(g.reserve_marker(), m1);
  {
    ScopedMarker s(g);
    s.mark(7);
    g.add_darts(10);  // markers grow with the map
    s.mark(50);
    EXPECT_TRUE(s.test(50));
  }
  ScopedMarker again(g);
  EXPECT_FALSE(again.test(7));  // cleared on release
}

TEST(Map, LinkedDartsAreAddedWithTheirLinks) {
  // A square (8 darts) glued to a second square built by add_linked_darts: the new darts' 0- and
  // 1-links copy the first square's shifted by 8, their 2-links lead back to it (and are written
  // there by hand, as a rewrite writes the preserved side).
  Map g = make_polygon(4);
  const Dart first = g.add_linked_darts(8, [&](int i, Dart base, LinkAppender& out) {
    if (i == 2) {
      out.append(8, [](size_t x) { return static_cast<Dart>(x); });
      return;
    }
    out.append(
        3, [&g, i, base](size_t x) { return base + g.alpha(i, static_cast<Dart>(x)); });  // blocks
    out.append(5, [&g, i, base](size_t x) { return base + g.alpha(i, static_cast<Dart>(x + 3)); });
  });
  EXPECT_EQ(first, 8u);
  EXPECT_EQ(g.capacity(), 16u);
  for (Dart d = 0; d < 8; ++d) g.set_alpha(2, d, d + 8);
  for (Dart d = 0; d < 8; ++d)
    for (int i = 0; i < 2; ++i) EXPECT_EQ(g.alpha(i, d + 8), g.alpha(i, d) + 8) << d;
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(count_cells(g, 2), 2u);
}

TEST(Map, LinkedDartsWithMissingLinksLeaveTheMapUnchanged) {
  Map g = make_polygon(3);
  const int m = g.reserve_marker();
  const Map before = g;
  try {
    g.add_linked_darts(4, [](int i, Dart base, LinkAppender& out) {
      out.append(i == 1 ? 3 : 4, [base](size_t x) { return base + static_cast<Dart>(x); });
    });
    ADD_FAILURE() << "a fill of 3 links for 4 darts was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Usage);
    EXPECT_NE(std::string(e.what()).find("1-links"), std::string::npos) << e.what();
  }
  EXPECT_THROW(g.add_linked_darts(
                   2, [](int, Dart, LinkAppender&) { throw Error(ErrorCode::Range, "fill"); }),
               Error);
  EXPECT_EQ(g.capacity(), before.capacity());
  for (int i = 0; i <= 2; ++i) EXPECT_EQ(g.links(i), before.links(i)) << i;
  EXPECT_EQ(g.add_darts(70), 6u);  // the markers and the dead set regrow clean
  for (Dart d = 6; d < 76; ++d) {
    EXPECT_TRUE(g.alive(d)) << d;
    EXPECT_FALSE(g.is_marked(d, m)) << d;
  }
  g.release_marker(m);
}

TEST(Map, ResizeForOverwriteGivesAnEmptyMapDartsToWrite) {
  // The links of a dropped map go back to the pool; a map resized for overwrite may get them with
  // their old contents, which the caller overwrites (here: 300 isolated edges).
  { Map dropped = make_polygon(300); }
  Map g(1);
  const int m = g.reserve_marker();
  g.resize_for_overwrite(600);
  ASSERT_EQ(g.capacity(), 600u);
  EXPECT_EQ(g.size(), 600u);
  for (int i = 0; i <= 1; ++i) {
    ASSERT_EQ(g.links(i).size(), 600u);
    Dart* l = g.link_data(i);
    for (Dart d = 0; d < 600; ++d) l[d] = i == 0 ? d ^ 1 : d;
  }
  for (Dart d = 0; d < 600; ++d) {
    EXPECT_TRUE(g.alive(d)) << d;
    EXPECT_FALSE(g.is_marked(d, m)) << d;
  }
  EXPECT_EQ(g.alpha(0, 2), 3u);
  EXPECT_EQ(g.count_links(0), 300u);
  EXPECT_EQ(g.count_links(1), 600u);
  EXPECT_TRUE(is_valid(g));
  g.release_marker(m);
  // Only an empty map: a map with darts is refused and left as it was.
  Map h = make_polygon(3);
  const Map before = h;
  EXPECT_THROW(h.resize_for_overwrite(10), Error);
  EXPECT_EQ(h.capacity(), before.capacity());
  for (int i = 0; i <= 2; ++i) EXPECT_EQ(h.links(i), before.links(i)) << i;
}

TEST(Map, BitsetShrunkThenRegrownReadsZeroPastTheCut) {
  Bitset b;
  b.resize(100);
  b.set(64);
  b.set(70);
  b.resize(65);
  b.resize(100);
  EXPECT_TRUE(b.test(64));
  EXPECT_FALSE(b.test(70));
  EXPECT_EQ(b.count(), 1u);
}

TEST(Map, MemoryPerDart) {
  for (int n : {2, 3}) {
    Map g = n == 2 ? make_torus(100, 100, 2) : make_polycube(menger_voxels(2));
    const double per = double(g.memory_bytes()) / double(g.size());
    EXPECT_LE(per, 4.0 * (n + 1) + 8) << n;
  }
}

TEST(Map, RejectsBadDimensions) {
  EXPECT_THROW(Map(-1), Error);
  EXPECT_THROW(Map(40), Error);
  EXPECT_THROW(Map(0, MapKind::OMap), Error);
  Map o(3, MapKind::OMap);
  EXPECT_FALSE(o.has_dim(0));
  EXPECT_TRUE(o.has_dim(1));
  EXPECT_FALSE(o.is_involutive_dim(1));
  EXPECT_TRUE(o.is_involutive_dim(2));
}

TEST(Builders, LiftAddsFreeDimensions) {
  Map cube = make_cube();
  cube.remove_dart(cube.add_dart());  // a hole in the index range is kept as a hole
  const Map lifted = lift(cube, 3);
  EXPECT_EQ(lifted.dimension(), 3);
  EXPECT_EQ(lifted.size(), 48u);
  EXPECT_FALSE(lifted.alive(48));
  EXPECT_TRUE(is_valid(lifted));
  EXPECT_EQ(count_all_cells(lifted),
            (std::vector<size_t>{8, 12, 6, 1}));  // one volume bounded by the surface
  for (Dart d : lifted.darts()) {
    EXPECT_TRUE(lifted.is_free(3, d));
    for (int i = 0; i <= 2; ++i) EXPECT_EQ(lifted.alpha(i, d), cube.alpha(i, d));
  }
  EXPECT_EQ(lift(cube, 2).size(), 48u);
  EXPECT_THROW(lift(cube, 1), Error);
}

TEST(Builders, PolycubeAndMenger) {
  Map m = make_polycube(menger_voxels(1));
  EXPECT_TRUE(is_valid(m));
  EXPECT_EQ(m.size(), 20u * 48u);
  EXPECT_EQ(count_cells(m, 3), 20u);
  EXPECT_EQ(count_components(m), 1u);
  // Level-1 sponge: 20 cubes, 24 shared faces... each internal face is 2 half-faces.
  EXPECT_EQ(count_orbits(m, OrbitType{0, 1}), 120u);
  EXPECT_EQ(count_cells(m, 2), 120u - 24u);
  EXPECT_THROW(make_polycube({{0, 0, 0}, {0, 0, 0}}), Error);
  EXPECT_EQ(menger_voxels(2).size(), 400u);
}

TEST(Builders, MengerPolycube) {
  auto sorted = [](std::vector<Voxel> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(sorted(menger_polycube_voxels(1, 1, 1)), sorted(menger_voxels(1)));
  // (2,2,2): the inference paper's §9.2.2 counts (81 volumes; its 270 faces and 216 vertices are
  // those of the boundary surface, of genus 28).
  const Map m = make_polycube(menger_polycube_voxels(2, 2, 2));
  EXPECT_TRUE(is_valid(m));
  EXPECT_EQ(count_cells(m, 3), 81u);
  EXPECT_EQ(count_cells(m, 2), 81u * 6 - 108);  // 108 faces shared by two voxels
  EXPECT_EQ(count_boundary_cells(m), 270u);
  EXPECT_EQ(count_cells(m, 0), 216u);  // every grid point touches a hole
  // Boundary surface: 4 darts per edge (two faces, two darts each), chi = V - E + F = 2 - 2 * 28.
  const auto boundary_edges = static_cast<long long>(free_darts(m, 3).size() / 4);
  EXPECT_EQ(216 - boundary_edges + 270, 2 - 2 * 28);
  EXPECT_EQ(menger_polycube_voxels(0, 0, 0).size(), 1u);
  EXPECT_THROW(menger_polycube_voxels(-1, 0, 0), Error);
}
