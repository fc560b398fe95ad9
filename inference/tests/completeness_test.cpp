// Completeness and soundness of folding (thesis App. C) by exhaustive search on small maps: for
// every connected G-map of a few darts (model/graph/map_family.hpp, one per isomorphism class),
// every orbit type and every start dart a, folding succeeds if and only if SOME graph scheme P of
// that orbit type instantiates to G with (b,h) ↦ O[b] (the start dart preserved at index 0).
//
// The oracle is independent of Algorithm 6: it enumerates every way of cutting G \ O into blocks of
// |O| darts indexed by the orbit darts (the instantiations of the other nodes), and accepts an
// assignment when every node can give each dimension d either an explicit arc (all (b,v) d-linked
// to (b,w) for one node w) or an implicit arc at a position p ((b,v) d-linked to (nb(b,p),v) for
// all b), positions used at most once (Def. 86: a relabeling is injective), the hook's decoration
// being <o> itself.
#include <gtest/gtest.h>

#include <functional>

#include "inference/dart_mapping.hpp"
#include "inference/fold.hpp"
#include "inference/fold_check.hpp"
#include "inference/infer.hpp"
#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/graph/map_family.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::inference;
using namespace gmr::graph;
using namespace gmr::scheme;

namespace {

struct Oracle {
  const Map& g;
  const OrbitType& o;
  std::vector<Dart> orbit_darts;  // O[b]
  std::vector<uint32_t> nb;       // nb[b * |o| + p]
  size_t s = 0;
  std::vector<std::vector<Dart>> blocks;  // blocks[v][b] = dart (b, v); block 0 = O
  std::vector<uint32_t> node_of, index_of;

  Oracle(const Map& gm, const OrbitType& ot, Dart a) : g(gm), o(ot) {
    orbit_darts = orbit(g, o, a);  // BFS order, a first (Alg. 4)
    s = orbit_darts.size();
    node_of.assign(g.capacity(), UINT32_MAX);
    index_of.assign(g.capacity(), UINT32_MAX);
    for (uint32_t b = 0; b < s; ++b) {
      node_of[orbit_darts[b]] = 0;
      index_of[orbit_darts[b]] = b;
    }
    for (uint32_t b = 0; b < s; ++b)
      for (size_t p = 0; p < o.size(); ++p) nb.push_back(index_of[g.alpha(o[p], orbit_darts[b])]);
    blocks.push_back(orbit_darts);
  }

  bool explicit_ok(uint32_t v, int d) const {
    const Dart x0 = g.alpha(d, blocks[v][0]);
    const uint32_t w = node_of[x0];
    for (uint32_t b = 0; b < s; ++b) {
      const Dart x = g.alpha(d, blocks[v][b]);
      if (node_of[x] != w || index_of[x] != b) return false;
    }
    return true;
  }
  bool implicit_ok(uint32_t v, int d, size_t p) const {
    for (uint32_t b = 0; b < s; ++b) {
      const Dart x = g.alpha(d, blocks[v][b]);
      if (node_of[x] != v || index_of[x] != nb[b * o.size() + p]) return false;
    }
    return true;
  }
  // Some choice, for every dimension, of an explicit arc or a distinct position.
  bool node_ok(uint32_t v) const {
    const int n = g.dimension();
    if (v == 0) {
      for (int d = 0; d <= n; ++d)
        if (!o.contains(d) && !explicit_ok(0, d)) return false;
      return true;
    }
    std::function<bool(int, DimMask)> assign = [&](int d, DimMask used) -> bool {
      if (d > n) return true;
      if (explicit_ok(v, d) && assign(d + 1, used)) return true;
      for (size_t p = 0; p < o.size(); ++p)
        if (!((used >> p) & 1u) && implicit_ok(v, d, p) && assign(d + 1, used | (DimMask(1) << p)))
          return true;
      return false;
    };
    return assign(0, 0);
  }

  bool all_nodes_ok() const {
    for (uint32_t v = 0; v < blocks.size(); ++v)
      if (!node_ok(v)) return false;
    return true;
  }

  // Cuts the unassigned darts into indexed blocks; true if some cut is a scheme's instantiation.
  bool search() {
    Dart first = kNoDart;
    for (Dart x : g.darts())
      if (node_of[x] == UINT32_MAX) {
        first = x;
        break;
      }
    if (first == kNoDart) return all_nodes_ok();
    const auto v = static_cast<uint32_t>(blocks.size());
    blocks.emplace_back(s, kNoDart);
    std::function<bool(uint32_t)> fill = [&](uint32_t b) -> bool {
      if (b == s) return search();
      if (blocks[v][b] != kNoDart) return fill(b + 1);
      for (Dart x : g.darts()) {
        if (node_of[x] != UINT32_MAX) continue;
        node_of[x] = v;
        index_of[x] = b;
        blocks[v][b] = x;
        if (fill(b + 1)) return true;
        node_of[x] = UINT32_MAX;
        index_of[x] = UINT32_MAX;
        blocks[v][b] = kNoDart;
      }
      return false;
    };
    // The smallest unassigned dart is in the new block, at any index.
    bool found = false;
    for (uint32_t b = 0; b < s && !found; ++b) {
      node_of[first] = v;
      index_of[first] = b;
      blocks[v][b] = first;
      found = fill(0);
      if (!found) {
        node_of[first] = UINT32_MAX;
        index_of[first] = UINT32_MAX;
        blocks[v][b] = kNoDart;
      }
    }
    if (!found) blocks.pop_back();
    return found;
  }
};

void check_family(int n, size_t max_darts, size_t& folded, size_t& failed) {
  for (size_t k = 1; k <= max_darts; ++k)
    for (const Map& g : connected_maps(n, MapKind::GMap, k)) {
      const JointGraph j = joint_from_map(g);
      for (const OrbitType& o : all_orbit_types(n))
        for (Dart a : g.darts()) {
          if (g.size() % orbit(g, o, a).size() != 0)
            continue;  // no scheme can exist; fold must fail
          const FoldResult f = fold(j, o, a);
          Oracle oracle(g, o, a);
          const bool exists = oracle.search();
          EXPECT_EQ(f.ok(), exists)
              << n << "-G-map of " << k << " darts, " << o.str() << " from dart " << a
              << (f.ok() ? "" : ": " + f.failure.message);
          if (f.ok()) {
            EXPECT_EQ(instantiation_mismatch(f, j), "");
            ++folded;
          } else {
            ++failed;
          }
        }
    }
}

}  // namespace

TEST(FoldCompleteness, ExhaustiveOnSmallMaps) {
  size_t folded = 0, failed = 0;
  check_family(1, 6, folded, failed);
  check_family(2, 6, folded, failed);
  check_family(3, 4, folded, failed);
  EXPECT_GT(folded, 100u);
  EXPECT_GT(failed, 10u);
  std::cout << folded << " folds, " << failed << " failures, each confirmed by exhaustive search\n";
}

// The driver's marking after a failure (infer.hpp): a start x in a node of the failed fold whose
// decoration is full and has the set of <o> is skipped. Exhaustively, no scheme of that orbit type
// instantiates to the map with x preserved at index 0 either (the oracle above), so skipping x
// loses no rule.
TEST(FoldCompleteness, StartsMarkedAfterAFailureFailToo) {
  size_t checked = 0;
  for (auto [n, max_darts] :
       {std::pair{1, size_t{6}}, std::pair{2, size_t{6}}, std::pair{3, size_t{4}}})
    for (size_t k = 1; k <= max_darts; ++k)
      for (const Map& g : connected_maps(n, MapKind::GMap, k)) {
        const JointGraph j = joint_from_map(g);
        for (const OrbitType& o : all_orbit_types(n))
          for (Dart a : g.darts()) {
            const FoldResult f = fold(j, o, a);
            if (f.ok()) continue;
            for (uint32_t x : equivalent_starts(f)) {
              ++checked;
              EXPECT_FALSE(Oracle(g, o, j.origin(x)).search())
                  << n << "-G-map of " << k << " darts, " << o.str() << ": the fold from " << a
                  << " fails, the one from " << x << " can succeed";
            }
          }
      }
  EXPECT_GT(checked, 100u);
  std::cout << checked << " skipped starts, each confirmed by exhaustive search\n";
}

// The same on joint representations of before/after pairs (κ, several orbit types failing after
// many nodes): the second quad subdivision and Doo–Sabin steps of a cube, every orbit type and
// start.
TEST(FoldCompleteness, StartsMarkedAfterAFailureFailTooOnJointGraphs) {
  size_t checked = 0;
  for (const char* rule : {"quad_subdivision", "doo_sabin_subdivision"}) {
    const RuleScheme s = io::read_scheme_file(
        gmr::testing::source_path("tools/data/rules/" + std::string(rule) + ".json"));
    const Map cube = make_cube();
    Map once = cube;
    ASSERT_TRUE(scheme::apply(SchemeEngine(s), once, {0}).applied);
    Map after = once;
    ASSERT_TRUE(scheme::apply(SchemeEngine(s), after, {0}).applied);
    const JointGraph j = joint_from_pair(once, after, identity_mapping(once, after));
    for (const OrbitType& o : all_orbit_types(2)) {
      std::vector<uint8_t> seen(j.size(), 0);
      for (uint32_t a = 0; a < once.size(); ++a) {
        if (seen[a]) continue;
        const FoldResult f = fold(j, o, a);
        if (f.ok()) continue;
        for (uint32_t x : equivalent_starts(f)) {
          if (seen[x]) continue;
          seen[x] = 1;
          ++checked;
          EXPECT_FALSE(fold(j, o, x).ok()) << rule << ", " << o.str() << ": the fold from " << a
                                           << " fails, the one from " << x << " succeeds";
        }
      }
    }
  }
  EXPECT_GT(checked, 100u);
}
