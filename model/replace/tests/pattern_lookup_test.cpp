// Pattern lookup (Damiand & Nivoliers 2022 Def. 5, §6.3): the lockstep minimum over the start
// darts against the plain minimum of boundary_word, and the store's lookup by the word of one
// start dart against the signature and the hash table, on the 6209 hex-conformal configurations
// and the repository's pattern sets.
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/replace/configurations.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/pattern_store.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

// The configuration's volume, with its orientation classes in oriented mode.
BoundaryGraph boundary_of(const Configuration& c, Mode mode = Mode::Unoriented) {
  return cell_boundary(
      c.map.map, 3, c.cell, c.map.flag,
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
  EXPECT_LT(s.darts.size(), 48u);                 // of the 48 flagged darts
  // The cube's symmetries keeping edge 0: the half-turn about the axis through its midpoint, the
  // two mirrors containing or bisecting it, and the identity.
  EXPECT_EQ(minimal_signature(b, Mode::Unoriented).automorphisms, 4u);
  EXPECT_EQ(minimal_signature(b, Mode::Oriented).automorphisms, 2u);
}

// Checks a lookup by the word from cell start s against the minimal signature: the same key's
// patterns, and for each of them the ranks give an isomorphism from the pattern's boundary (in
// its template order) onto the cell's, preserving neighbours, flags and, in oriented mode, D+.
void expect_lookup_by_one_word(const PatternStore& store, const BoundaryGraph& b, int cell_dim,
                               uint32_t s, const std::string& what) {
  Word key{static_cast<uint32_t>(cell_dim)};
  boundary_word(b, s, key);
  const StoreMatch m = store.match_word(key, s);
  ASSERT_EQ(m.hits, store.find(store_key(b, cell_dim, store.mode()))) << what;
  if (!m.hits) return;
  ASSERT_EQ(m.ranks->size(), m.hits->size()) << what;
  const std::vector<uint32_t> order = boundary_labeling(b, s);
  for (size_t h = 0; h < m.hits->size(); ++h) {
    const StoreEntry& e = (*m.hits)[h];
    const BoundaryGraph& pb = store.patterns()[e.pattern].boundary;
    const std::vector<uint32_t> ref = boundary_labeling(pb, e.start);
    const std::vector<uint32_t>& rank = (*m.ranks)[h];
    ASSERT_EQ(rank.size(), b.size()) << what;
    std::vector<uint32_t> f(pb.size());  // pattern local index -> cell local index
    for (size_t k = 0; k < ref.size(); ++k) f[ref[k]] = order[rank[k]];
    for (uint32_t x = 0; x < pb.size(); ++x) {
      ASSERT_EQ(b.flag[f[x]] != 0, pb.flag[x] != 0) << what;
      if (store.mode() == Mode::Oriented) {
        ASSERT_EQ(b.positive[f[x]], pb.positive[x]) << what;
      }
      for (int j = 0; j < b.arity; ++j)
        ASSERT_EQ(b.neighbour(f[x], j), f[pb.neighbour(x, j)]) << what;
    }
  }
}

// Lookup by one word equals lookup by the minimal signature, from every start dart of every
// configuration, for a store holding every other class (so both hits and misses occur); the
// store's match (first start) agrees too.
TEST(PatternLookup, LookupByOneWordIsLookupBySignature) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    std::unordered_map<Word, size_t, WordHash> classes;
    PatternStore store(mode);
    for (const Configuration& c : set.configurations) {
      const Word key = store_key(boundary_of(c, mode), 3, mode);
      if (!classes.emplace(key, classes.size()).second || classes.size() % 2 == 0) continue;
      store.add(make_pattern("class" + std::to_string(classes.size()),
                             FlaggedMap{lift(c.map.map, 3), c.map.flag, {}}));
    }
    size_t hits = 0, misses = 0;
    for (size_t i = 0; i < set.configurations.size(); i += 3) {
      const BoundaryGraph b = boundary_of(set.configurations[i], mode);
      const StartSet starts = start_darts(b, mode);
      ASSERT_EQ(first_start_dart(b, mode), starts.darts.front()) << i;
      for (uint32_t s : starts.darts) {
        expect_lookup_by_one_word(store, b, 3, s, std::to_string(i) + " " + to_string(mode));
        Word w;
        std::vector<uint32_t> order;
        boundary_word(b, s, w, order);  // the word and the labelling in one traversal
        EXPECT_EQ(w, boundary_word(b, s)) << i;
        EXPECT_EQ(order, boundary_labeling(b, s)) << i;
      }
      const StoreMatch m = store.match(b, 3);
      ASSERT_EQ(m.hits, store.find(store_key(b, 3, mode))) << i;
      if (m.hits) {
        EXPECT_EQ(m.start, starts.darts.front()) << i;
      }
      ++(m.hits ? hits : misses);
    }
    EXPECT_GT(hits, 0u);
    EXPECT_GT(misses, 0u);
    EXPECT_EQ(store.keys(), (classes.size() + 1) / 2);
  }
}

// The same on the pattern sets of the repository and the configurations they are made for (faces
// of polygons with split edges, marching-cubes volumes), and on the patterns' own boundaries,
// including duplicate keys (the chiral pairs of marching-cubes in unoriented mode).
TEST(PatternLookup, LookupByOneWordOnThePatternSets) {
  struct Case {
    const char* patterns;
    const char* configurations;
  };
  for (const Case& k :
       {Case{"conformal-faces", "square-edges"}, Case{"tet-to-hex", "triangle-edges"},
        Case{"hex-subdivision", "square-edges"}, Case{"marching-cubes", "marching-cubes"}}) {
    const std::vector<Pattern> ps = load_patterns(testing::patterns_dir(k.patterns));
    const ConfigurationSet set = generate_configurations(k.configurations);
    for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
      PatternStore store(mode);
      for (const Pattern& p : ps) store.add(p);
      const std::string what = std::string(k.patterns) + " " + to_string(mode);
      size_t hits = 0;
      for (const Configuration& c : set.configurations) {
        const BoundaryGraph b = cell_boundary(
            c.map.map, set.cell_dim, c.cell, c.map.flag,
            mode == Mode::Oriented ? orientation_classes(c.map.map) : std::vector<uint8_t>{});
        for (uint32_t s : start_darts(b, mode).darts)
          expect_lookup_by_one_word(store, b, set.cell_dim, s, what);
        hits += store.match(b, set.cell_dim).hits != nullptr;
      }
      EXPECT_GT(hits, 0u) << what;
      for (const Pattern& p : ps)
        for (uint32_t s : start_darts(p.boundary, mode).darts)
          expect_lookup_by_one_word(store, p.boundary, p.cell_dim, s, what + " " + p.name);
    }
  }
}

}  // namespace
}  // namespace gmr::replace
