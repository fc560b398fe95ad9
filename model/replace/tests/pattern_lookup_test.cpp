// Pattern lookup (Damiand & Nivoliers 2022 Def. 5, §6.3): the lockstep minimum over the start
// darts against the plain minimum of boundary_word, and the store's profile lookup against the
// signature and the hash table, on the 6209 hex-conformal configurations.
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/replace/configurations.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/pattern_store.hpp"

namespace gmr::replace {
namespace {

// The configuration's volume, with its orientation classes in oriented mode.
BoundaryGraph boundary_of(const Configuration& c, Mode mode = Mode::Unoriented) {
  return cell_boundary(c.map.map, 3, c.cell, c.map.flag,
                       mode == Mode::Oriented ? orientation_classes(c.map.map) : std::vector<uint8_t>{});
}

// Every start of the start set streamed on its own: the minimum, its first start and its count.
TEST(PatternLookup, LockstepMinimumIsTheMinimumOverTheStartDarts) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  for (size_t i = 0; i < set.configurations.size(); i += 7) {
    for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
      const BoundaryGraph b = boundary_of(set.configurations[i], mode);
      const StartSet starts = start_darts(b, mode);
      ASSERT_FALSE(starts.darts.empty());
      Word least;
      uint32_t first = 0, count = 0;
      for (uint32_t s : starts.darts) {
        const Word w = boundary_word(b, s);
        if (count == 0 || w < least) {
          least = w;
          first = s;
          count = 1;
        } else if (w == least) {
          ++count;
        }
      }
      const CellSignature sig = minimal_signature(b, mode);
      ASSERT_EQ(sig.word, least) << i;
      EXPECT_EQ(sig.start, first) << i;
      EXPECT_EQ(sig.automorphisms, count) << i;
      EXPECT_EQ(first_start_with_word(b, starts, least), first) << i;
    }
  }
}

// The start set keeps only darts with the smallest (face size, face size across the edge): on a
// cube with one split edge, the flagged darts in the two unsplit faces next to the split edge.
TEST(PatternLookup, StartSetIsRestrictedByFaceSizes) {
  const ConfigurationSet set = generate_configurations("hex-edges");
  const Configuration& one = set.configurations.front();  // edge 0 split
  ASSERT_EQ(one.split, std::vector<int>{0});
  const BoundaryGraph b = boundary_of(one, Mode::Oriented);
  const StartSet s = start_darts(b, Mode::Unoriented);
  EXPECT_EQ(s.invariant, uint64_t(8) << 32 | 8);  // two quads of 8 darts
  EXPECT_EQ(s.faces, 6u);
  EXPECT_EQ(s.face_squares, 4u * 64 + 2u * 100);  // four quads, two faces with a split edge
  EXPECT_LT(s.darts.size(), 48u);  // of the 48 flagged darts
  // The cube's symmetries keeping edge 0: the half-turn about the axis through its midpoint, the
  // two mirrors containing or bisecting it, and the identity.
  EXPECT_EQ(minimal_signature(b, Mode::Unoriented).automorphisms, 4u);
  EXPECT_EQ(minimal_signature(b, Mode::Oriented).automorphisms, 2u);
}

// The store's match (profile, one word comparison or the signature) agrees with store_key + find
// on every configuration, for a store holding every other class (so both hits and misses occur).
TEST(PatternLookup, StoreMatchAgreesWithTheSignatureAndTheHashTable) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    std::unordered_map<Word, size_t, WordHash> classes;
    PatternStore store(mode);
    for (const Configuration& c : set.configurations) {
      const Word key = store_key(boundary_of(c, mode), 3, mode);
      if (!classes.emplace(key, classes.size()).second || classes.size() % 2 == 0) continue;
      store.add(make_pattern("class" + std::to_string(classes.size()), FlaggedMap{lift(c.map.map, 3), c.map.flag, {}}));
    }
    size_t hits = 0, misses = 0;
    for (size_t i = 0; i < set.configurations.size(); ++i) {
      const BoundaryGraph b = boundary_of(set.configurations[i], mode);
      StoreEntry e;
      const Word key = store_key(b, 3, mode, &e);
      const StoreMatch m = store.match(b, 3);
      ASSERT_EQ(m.hits, store.find(key)) << i << " " << to_string(mode);
      if (m.hits) {
        ++hits;
        EXPECT_EQ(m.start, e.start) << i;
      } else {
        ++misses;
      }
    }
    EXPECT_GT(hits, 0u);
    EXPECT_GT(misses, 0u);
    EXPECT_EQ(store.keys(), (classes.size() + 1) / 2);
  }
}

}  // namespace
}  // namespace gmr::replace
