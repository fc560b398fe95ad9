// Matches (model/match.hpp) and derivations on maps (model/dpo.hpp).
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rule_io/rule_json.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::io;

namespace {
// The 2-sewing of two free edges (thesis Fig. 3.19a).
const char* kSew = R"({"format":"gmr.rule","version":1,"kind":"concrete","map":"gmap","n":2,
  "left":{"nodes":["a","b","c","d"],"links":[{"nodes":["a","b"],"label":0},{"nodes":["c","d"],"label":0},
     {"nodes":["a","a"],"label":2},{"nodes":["b","b"],"label":2},{"nodes":["c","c"],"label":2},{"nodes":["d","d"],"label":2}]},
  "right":{"nodes":["a","b","c","d"],"links":[{"nodes":["a","b"],"label":0},{"nodes":["c","d"],"label":0},
     {"nodes":["a","c"],"label":2},{"nodes":["b","d"],"label":2}]}})";

// Two free edges 0-1 and 2-3 (1-loops): the map kSew applies to.
Map free_edges() {
  Map g(2);
  g.add_darts(4);
  g.link(0, 0, 1);
  g.link(0, 2, 3);
  return g;
}
}  // namespace

TEST(Match, EnumeratesAllInjectiveMatches) {
  const Rule r = parse_rule(kSew);
  const Map g = free_edges();
  const auto ms = find_map_matches(r, g);
  // (a,b) on one edge in 2 orientations, (c,d) on the other in 2, and the edges swapped: 8.
  EXPECT_EQ(ms.size(), 8u);
  const DGraph dg = to_dgraph(g);
  for (const auto& m : find_matches(r.left(), dg)) {
    check_match(r, dg, m);  // throws on a bad match
    EXPECT_TRUE(satisfies_gluing(r, dg, m));
  }
}

TEST(Match, AnchoredMatchingPropagates) {
  const Rule r = parse_rule(kSew);
  const Map g = free_edges();
  const DGraph dg = to_dgraph(g);
  auto m = anchored_match(r.left(), dg, {{Node(0), Node(1)}, {Node(2), Node(3)}});
  ASSERT_TRUE(m);
  EXPECT_EQ(m->node, (NodeMap{Node(1), Node(0), Node(3), Node(2)}));
  EXPECT_FALSE(
      anchored_match(r.left(), dg, {{Node(0), Node(1)}, {Node(2), Node(0)}}));  // injectivity
  EXPECT_THROW(anchored_match(r.left(), dg, {{Node(0), Node(1)}}), Error);      // c, d unreachable
  DGraph L;
  L.add_node("a");
  L.add_node("b");
  L.add_arc(Node(0), Node(1), 0);
  L.add_arc(Node(0), Node(0), 0);
  EXPECT_THROW(anchored_match(L, dg, {{Node(0), Node(0)}}), Error);  // L not combinatorial
}

TEST(Dpo, SewOnMapsBothWays) {
  const Rule r = parse_rule(kSew);
  const Map g = free_edges();
  const std::vector<Dart> m{0, 1, 2, 3};
  const MapDerivation a = apply(r, g, m, Construction::Rewriting),
                      b = apply(r, g, m, Construction::Categorical);
  EXPECT_TRUE(is_valid(a.H));
  EXPECT_TRUE(is_isomorphic(a.H, b.H));
  EXPECT_EQ(a.H.alpha(2, 0), 2u);
  EXPECT_EQ(a.comatch, b.comatch);
}

TEST(Dpo, DanglingArcIsNamed) {
  // Delete a node of a 0-link without matching its 0-arcs.
  DGraph L, R;
  L.add_node("a");
  const Rule r(L, R, 1);
  Map g(1);
  g.add_darts(2);
  g.link(0, 0, 1);
  const DGraph dg = to_dgraph(g);
  const auto ms = find_matches(r.left(), dg);
  ASSERT_EQ(ms.size(), 2u);
  const auto d = dangling_arcs(r, dg, ms[0]);
  ASSERT_FALSE(d.empty());
  EXPECT_NE(d[0].describe(r, dg).find("dangling"), std::string::npos);
  try {
    derive(r, dg, ms[0]);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Usage);
    EXPECT_EQ(e.location(), "match of a");
  }
  EXPECT_THROW(apply(r, g, {0}), Error);
}

TEST(Dpo, NonCombinatorialResultIsAnError) {
  // Adds a second 0-arc at a preserved node: H is no map.
  DGraph L, R;
  L.add_node("a");
  R.add_node("a");
  R.add_node("x");
  R.add_link(Node(0), Node(1), 0);
  R.add_arc(Node(1), Node(1), 1);
  const Rule r(L, R, 1);
  Map g(1);
  g.add_darts(1);
  EXPECT_THROW(apply(r, g, {0}), Error);
  EXPECT_THROW(apply(r, g, {0}, Construction::Categorical), Error);
}
