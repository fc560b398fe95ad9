// Signatures of cell and pattern boundaries (Damiand & Nivoliers 2022 Defs. 3–5 on G-maps).
#include "model/replace/flagged_word.hpp"

#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/signature.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/pattern_store.hpp"

namespace gmr::replace {
namespace {

BoundaryGraph face_of(const Map& g, const std::vector<uint32_t>& flag = {}) {
  return cell_boundary(g, 2, 0, flag, orientation_classes(g));
}

// The unflagged words of a square and a triangle (alpha_0 then alpha_1) are the same from every
// start dart: the polygon's dihedral symmetry acts transitively on its darts.
TEST(FlaggedWord, SquareAndTriangleWordsFromEveryStart) {
  const Word square{2, 3, 1, 4, 5, 1, 6, 2, 3, 7, 4, 8, 8, 5, 7, 6};
  const Word triangle{2, 3, 1, 4, 5, 1, 6, 2, 3, 6, 4, 5};
  const BoundaryGraph s = face_of(make_polygon(4)), t = face_of(make_polygon(3));
  ASSERT_EQ(s.size(), 8u);
  ASSERT_EQ(t.size(), 6u);
  for (uint32_t k = 0; k < s.size(); ++k) EXPECT_EQ(boundary_word(s, k, false), square) << k;
  for (uint32_t k = 0; k < t.size(); ++k) EXPECT_EQ(boundary_word(t, k, false), triangle) << k;
  EXPECT_EQ(minimal_signature(s, Mode::Unoriented, false).automorphisms, 8u);
  EXPECT_EQ(minimal_signature(s, Mode::Oriented, false).automorphisms, 4u);
}

// The generic word without flags is the core library's BFS word of the same orbit.
TEST(FlaggedWord, AgreesWithCoreWordOnAClosedSurface) {
  const Map cube = make_cube(2);
  const BoundaryGraph b = cell_boundary(cube, 3, 0, {}, {});
  for (uint32_t k = 0; k < b.size(); k += 7)
    EXPECT_EQ(boundary_word(b, k, false), bfs_word(cube, b.dart[k])) << k;
}

// A cell boundary is numbered breadth-first from its first dart: its word from local dart 0 reads
// off its arrays. Every dart of a split cube's volume and of a flagged square as first dart, with
// flags that differ from dart to dart.
TEST(FlaggedWord, NumberedBoundaryWordIsTheWordFromTheFirstDart) {
  const Map cube = make_cube(3);
  std::vector<uint32_t> flags(cube.capacity());
  for (Dart d = 0; d < cube.capacity(); ++d) flags[d] = d % 3;
  for (Dart d = 0; d < cube.capacity(); d += 5) {
    const BoundaryGraph v = cell_boundary(cube, 3, d, flags, {}),
                        f = cell_boundary(cube, 2, d, flags, {});
    for (const BoundaryGraph* b : {&v, &f}) {
      Word read{7}, walked{7};
      numbered_boundary_word(*b, read);
      boundary_word(*b, 0, walked);
      EXPECT_EQ(read, walked) << d;
    }
  }
  // Not so for a pattern boundary (numbered in dart order): the word reads another numbering.
  const Map square = make_polygon(4);
  BoundaryGraph shuffled = cell_boundary(square, 2, 0, {}, {});
  std::swap(shuffled.dart[1], shuffled.dart[2]);
  for (uint32_t& y : shuffled.nbr) y = y == 1 ? 2 : y == 2 ? 1 : y;
  std::swap(shuffled.nbr[2], shuffled.nbr[4]);
  std::swap(shuffled.nbr[3], shuffled.nbr[5]);
  Word read, walked;
  numbered_boundary_word(shuffled, read);
  boundary_word(shuffled, 0, walked);
  EXPECT_NE(read, walked);
}

TEST(FlaggedWord, CubeAutomorphismsAndFlaggedWordPrefix) {
  const Map cube = make_cube(2);
  const std::vector<uint32_t> flags(cube.capacity(), 1);
  const BoundaryGraph b = cell_boundary(cube, 3, 0, flags, orientation_classes(cube));
  ASSERT_EQ(b.size(), 48u);
  const CellSignature u = minimal_signature(b, Mode::Unoriented),
                      o = minimal_signature(b, Mode::Oriented);
  EXPECT_EQ(u.automorphisms, 48u);
  EXPECT_EQ(o.automorphisms, 24u);
  EXPECT_EQ(u.word, o.word);  // the minimum is reached in both orientation classes
  ASSERT_EQ(u.word.size(), 4u * 48);
  const Word prefix{1, 2, 3, 4, 1, 1, 5, 6, 1, 7, 1, 8, 1, 6, 9, 1};
  EXPECT_TRUE(std::equal(prefix.begin(), prefix.end(), u.word.begin()));
}

// Flags break symmetry: one flagged dart on a square leaves only the identity.
TEST(FlaggedWord, FlagsKillAutomorphisms) {
  const Map sq = make_polygon(4);
  std::vector<uint32_t> flags(sq.capacity(), 0);
  flags[0] = 1;
  const CellSignature s = minimal_signature(face_of(sq, flags), Mode::Unoriented);
  EXPECT_EQ(s.automorphisms, 1u);
  EXPECT_EQ(s.word.front(), 1u);  // the start is flagged
  // Flagged and unflagged faces never share a signature.
  EXPECT_NE(s.word, minimal_signature(face_of(sq), Mode::Unoriented).word);
}

// Oriented mode needs a 2-colouring flipped by every link: an odd cycle of links has none.
TEST(FlaggedWord, OrientationClassesRejectOddCycles) {
  Map g(2);
  g.add_darts(3);
  g.link(0, 0, 1);
  g.link(1, 1, 2);
  g.link(2, 2, 0);
  EXPECT_THROW(orientation_classes(g), Error);
  EXPECT_NO_THROW(orientation_classes(make_cube(2)));
}

TEST(FlaggedWord, HashSeparatesWords) {
  WordHash h;
  EXPECT_NE(h(Word{1, 2, 3}), h(Word{1, 3, 2}));
  EXPECT_EQ(h(Word{4, 5}), h(Word{4, 5}));
}

}  // namespace
}  // namespace gmr::replace
