// A cell numbered along a known word (word_traversal.hpp), the half-cell count of the replacement
// room (half_cells.hpp), and query-replace's lookup through the word the previous cell matched
// (query_replace.cpp): each gives what the plain traversal, orbit count or lookup gives.
#include "model/replace/word_traversal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/replace/flagged_word.hpp"
#include "model/replace/half_cells.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/stride_prefetch.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/testing/random_maps.hpp"

namespace gmr::replace {
namespace {

using testing::all_flagged;

struct Bits {
  std::vector<uint64_t> words;
  explicit Bits(Dart n) : words((size_t(n) + 63) / 64, 0) {}
  MetBits met(Dart n) { return {words.data(), n}; }
  size_t count() const {
    size_t c = 0;
    for (uint64_t w : words) c += static_cast<size_t>(__builtin_popcountll(w));
    return c;
  }
};

// W(cell, d) without flags' dimension prefix: the letters follow_word reads.
Word word_from(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag) {
  Word w;
  numbered_boundary_word(cell_boundary(g, i, d, flag, {}), w);
  return w;
}

// From every dart of a cube (faces and the volume) and of a polycube, following the cell's own
// word from that dart numbers the darts as the breadth-first traversal does and meets exactly
// the orbit.
TEST(WordTraversal, FollowsTheCellsOwnWordAsTheTraversalNumbersIt) {
  for (const Map& g : {make_cube(2), make_polycube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}})}) {
    std::vector<uint32_t> flag(g.capacity(), 0);
    for (Dart d = 0; d < g.capacity(); d += 3) flag[d] = 1 + d % 2;  // flags of two values
    for (int i : {2, 3}) {
      for (Dart d = 0; d < g.capacity(); ++d) {
        const BoundaryGraph b = cell_boundary(g, i, d, flag, {});
        const Word w = word_from(g, i, d, flag);
        Bits bits(g.capacity());
        std::vector<Dart> out(b.size());
        ASSERT_TRUE(
            follow_word(g, i, d, w.data(), b.size(), flag, bits.met(g.capacity()), out.data()))
            << i << " " << d;
        EXPECT_EQ(out, b.dart);
        EXPECT_EQ(bits.count(), b.size());
        for (Dart x : b.dart) EXPECT_TRUE(bits.met(g.capacity()).test(x));
        // Flags cut after the last flagged dart: the darts past the end read unflagged.
        std::vector<uint32_t> cut(flag.begin(), flag.begin() + (g.capacity() - 1) / 3 * 3 + 1);
        Bits again(g.capacity());
        std::vector<Dart> out_cut(b.size());
        ASSERT_TRUE(
            follow_word(g, i, d, w.data(), b.size(), cut, again.met(g.capacity()), out_cut.data()));
        EXPECT_EQ(out_cut, b.dart);
      }
    }
  }
}

// A word that is not the cell's from that dart is refused and nothing stays met: another flag, a
// start dart with another word, a cell of another shape, and a covering (the square's boundary
// word followed on a 2-gon: every letter agrees locally, but darts would be numbered twice).
TEST(WordTraversal, RefusesOtherWordsAndLeavesNothingMet) {
  const Map cube = make_cube(2);
  std::vector<uint32_t> flag(cube.capacity(), 0);
  flag[0] = 1;
  const Word w0 = word_from(cube, 3, 0, flag);
  Bits bits(cube.capacity());
  std::vector<Dart> out(cube.capacity());
  const uint32_t n = static_cast<uint32_t>(cube.size());
  // Dart 0 is the only flagged dart: from any other dart the flags disagree.
  for (Dart d = 1; d < cube.capacity(); ++d) {
    EXPECT_FALSE(follow_word(cube, 3, d, w0.data(), n, flag, bits.met(cube.capacity()), out.data()))
        << d;
    EXPECT_EQ(bits.count(), 0u);
  }
  // The volume's word on a face; a met dart met again.
  EXPECT_FALSE(follow_word(cube, 2, 0, w0.data(), n, flag, bits.met(cube.capacity()), out.data()));
  EXPECT_EQ(bits.count(), 0u);
  bits.met(cube.capacity()).set(cube.alpha(2, 0));
  EXPECT_FALSE(follow_word(cube, 3, 0, w0.data(), n, flag, bits.met(cube.capacity()), out.data()));
  EXPECT_EQ(bits.count(), 1u);
  // The square's word (8 darts) on a 2-gon (4 darts): a 2-to-1 covering of its boundary graph.
  const Map square = make_polygon(4), digon = make_polygon(2);
  const std::vector<uint32_t> none;
  const Word ws = word_from(square, 2, 0, none);
  Bits small(digon.capacity());
  std::vector<Dart> out2(8);
  EXPECT_FALSE(
      follow_word(digon, 2, 0, ws.data(), 8, none, small.met(digon.capacity()), out2.data()));
  EXPECT_EQ(small.count(), 0u);
  // The 2-gon's own word does agree.
  const Word wd = word_from(digon, 2, 0, none);
  EXPECT_TRUE(
      follow_word(digon, 2, 0, wd.data(), 4, none, small.met(digon.capacity()), out2.data()));
}

// The sweep's next unmet dart (MetBits::next_clear) is the first clear bit at or after a dart, as
// a bit-by-bit scan finds it: sizes around word ends, bits set at random and in full words.
TEST(WordTraversal, NextClearIsTheFirstUnmetDartFromAPlace) {
  std::mt19937 rng(7);
  for (Dart n : {1u, 63u, 64u, 65u, 128u, 130u, 200u}) {
    for (int density : {0, 50, 95, 100}) {
      Bits b(n);
      const MetBits met = b.met(n);
      for (Dart x = 0; x < n; ++x)
        if (int(rng() % 100) < density) met.set(x);
      for (Dart from = 0; from <= n + 1; ++from) {
        Dart expected = n;
        for (Dart x = from; x < n; ++x)
          if (!met.test(x)) {
            expected = x;
            break;
          }
        EXPECT_EQ(met.next_clear(from), expected) << n << " " << density << " " << from;
      }
    }
  }
}

// The next cell's prefetch (stride_prefetch.hpp) is a hint: for predictions inside the map, past
// its end, below dart 0 (wrapping) and past the flags, it reads nothing it should not and changes
// neither the map nor the flags.
TEST(WordTraversal, PredictedCellPrefetchChangesNothing) {
  const Map g = make_polycube({{0, 0, 0}, {1, 0, 0}});
  const std::vector<uint32_t> flag(g.capacity() / 2, 1);  // the darts past half unflagged
  const Map before_map = g;
  const Dart cap = g.capacity();
  const std::vector<Dart> last{0, 5, cap - 1, 3, cap / 2, 1};
  const std::vector<Dart> before{0, 2, 0, 7, 1, cap - 1};  // strides 0, 3, beyond, below 0, ...
  for (int i : {2, 3})
    prefetch_predicted_cell(g, i, flag, last.data(), before.data(),
                            static_cast<uint32_t>(last.size()));
  EXPECT_TRUE(is_isomorphic(g, before_map));
  for (int i = 0; i <= 3; ++i) EXPECT_EQ(g.links(i), before_map.links(i));
  EXPECT_EQ(flag, std::vector<uint32_t>(cap / 2, 1));
}

// The half-cells of a map: per i-cell (<0..i-1, i+1>-orbit), two when alpha_{i+1} is not free,
// else one: on closed and open surfaces, a map with deleted darts, a polycube (faces shared or
// not, volumes) and a 2-G-map; in 3-G-maps the half-faces and half-volumes counted in one sweep
// too.
size_t halves_by_orbits(const Map& g, int i) {
  size_t h = 0;
  for (Dart d : orbit_representatives(g, cell_type(g, i)))
    h += g.dimension() > i && !g.is_free(i + 1, d) ? 2 : 1;
  return h;
}

TEST(HalfCells, CountIsTheCellsWithTheirTwoSides) {
  std::vector<Map> maps{make_cube(2),
                        make_cube(3),
                        make_grid(3, 2),
                        make_grid(3, 2, 3),
                        make_polygon(5),
                        make_stacked_cubes(),
                        make_polycube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {3, 0, 0}})};
  {
    // Deleted darts: a junk dart before a cube.
    Map g(2);
    const Dart junk = g.add_dart();
    const Map c = make_cube(2);
    const Dart base = g.add_darts(c.size());
    c.for_each_dart([&](Dart x) {
      for (int i = 0; i <= 2; ++i) g.set_alpha(i, base + x, base + c.alpha(i, x));
    });
    g.remove_dart(junk);
    maps.push_back(std::move(g));
  }
  for (int n : {2, 3}) {
    // Half-cells with free darts below i (walked breadth-first): a path d0 -0- d1 -1- d2, a free
    // dart, and a square.
    Map g(n);
    for (int k = 0; k < 4; ++k) g.add_dart();
    g.link(0, 0, 1);
    g.link(1, 1, 2);
    const Map sq = make_polygon(4, n);
    const Dart base = g.add_darts(sq.size());
    sq.for_each_dart([&](Dart x) {
      for (int i = 0; i <= n; ++i) g.set_alpha(i, base + x, base + sq.alpha(i, x));
    });
    maps.push_back(std::move(g));
  }
  for (const Map& g : maps) {
    ASSERT_TRUE(is_valid(g));
    for (int i : {2, 3}) {
      if (g.dimension() != i && g.dimension() != i + 1) continue;
      EXPECT_EQ(count_half_cells(g, i), halves_by_orbits(g, i))
          << g.dimension() << " " << i << " " << g.size();
    }
    if (g.dimension() == 3) {  // both in one sweep (the free-dart maps: the faces swept apart)
      const HalfFacesAndVolumes h = count_half_faces_and_volumes(g);
      EXPECT_EQ(h.faces, halves_by_orbits(g, 2)) << g.size();
      EXPECT_EQ(h.volumes, halves_by_orbits(g, 3)) << g.size();
      // The closed maps' one-loop count against the general sweeps, one dimension each.
      EXPECT_EQ(h.faces, count_half_cells(g, 2)) << g.size();
      EXPECT_EQ(h.volumes, count_half_cells(g, 3)) << g.size();
    }
  }
  {
    // A square whose half-face alpha_3 sends onto itself (the half-turn (alpha_0 alpha_1)^2, which
    // commutes with alpha_0 and alpha_1), alpha_2 free: one volume, a face with two half-faces.
    Map g = make_polygon(4, 3);
    for (Dart x = 0; x < g.capacity(); ++x) {
      const Dart turn = g.alpha(1, g.alpha(0, g.alpha(1, g.alpha(0, x))));
      g.set_alpha(3, x, turn);
    }
    ASSERT_TRUE(is_valid(g));
    const HalfFacesAndVolumes h = count_half_faces_and_volumes(g);
    EXPECT_EQ(h.faces, 2u);
    EXPECT_EQ(h.faces, halves_by_orbits(g, 2));
    EXPECT_EQ(h.volumes, 1u);
    EXPECT_EQ(h.volumes, count_half_cells(g, 3));
  }
  EXPECT_THROW(count_half_faces_and_volumes(make_cube(2)), Error);
}

// Query-replace looks a cell up through the word the previous cell matched when it agrees from the
// cell's dart. Each cell looked up alone (a list of one cell: no previous word) gives the same map,
// dart for dart, in both modes (in oriented mode only darts of D+ take that path): cubes with
// split edges under the conformal set (cells of several patterns and unmatched ones), and the
// hexahedral subdivision of a polycube, each also with its darts shuffled (cells then met at darts
// of both orientation classes).
TEST(QueryReplace, EachCellLookedUpAloneGivesTheSameMap) {
  auto same = [](const FlaggedMap& a, const FlaggedMap& b) {
    if (a.map.capacity() != b.map.capacity() || a.flag != b.flag || a.position != b.position)
      return false;
    for (int i = 0; i <= a.map.dimension(); ++i)
      if (a.map.links(i) != b.map.links(i)) return false;
    return true;
  };
  auto run = [&](FlaggedMap m, const PatternStore& store, int dim) {
    FlaggedMap alone = m;
    const QueryReplaceReport r = query_replace(m, store, dim);
    size_t replaced = 0;
    for (Dart d : orbit_representatives(alone.map, cell_type(alone.map, dim))) {
      const std::vector<Dart> one{d};
      replaced += query_replace(alone, store, dim, {}, {}, {}, &one).replaced();
    }
    EXPECT_EQ(r.replaced(), replaced);
    EXPECT_TRUE(same(m, alone));
    EXPECT_TRUE(is_valid(m.map));
    return m;
  };
  std::vector<Pattern> conformal = load_patterns(testing::patterns_dir("conformal-faces"));
  std::vector<Pattern> hex = load_patterns(testing::patterns_dir("hex-subdivision"));
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    PatternStore faces(mode), hexes(mode);
    for (const Pattern& p : conformal) faces.add(p);
    for (const Pattern& p : hex) hexes.add(p);
    for (bool shuffled : {false, true}) {
      std::mt19937 random(7);
      auto shuffle = [&](const Map& g) {
        if (!shuffled) return g;
        std::vector<Dart> perm(g.capacity());
        std::iota(perm.begin(), perm.end(), Dart{0});
        std::shuffle(perm.begin(), perm.end(), random);
        return ::gmr::testing::permute_darts(g, perm);
      };
      for (uint32_t mask = 1; mask < (1u << 12); mask += 331) {
        FlaggedMap m = all_flagged(shuffle(make_cube(2)));
        const std::vector<Dart> edges = orbit_representatives(m.map, cell_type(m.map, 1));
        for (size_t e = 0; e < edges.size(); ++e)
          if (mask >> e & 1) split_edge(m, edges[e], 2);
        run(m, faces, 2);
      }
      FlaggedMap block =
          all_flagged(shuffle(make_polycube({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}})));
      split_all_edges(block, 2);
      block = run(block, hexes, 2);
      run(block, hexes, 3);
    }
  }
}

}  // namespace
}  // namespace gmr::replace
