// Rule-scheme isomorphism (thesis Def. 90, Alg. 7).
#include "inference/scheme_isomorphism.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "inference/tests/inference_support.hpp"
#include "model/rule_io/scheme_json.hpp"

using namespace gmr;
using namespace gmr::inference;
using namespace gmr::io;
using namespace gmr::scheme;
using namespace gmr::inference::test;

namespace {

// The same scheme with the nodes of R listed in reverse order (arcs renumbered) and renamed.
RuleScheme shuffled(const RuleScheme& s) {
  RuleScheme t = s;
  const auto k = static_cast<uint32_t>(s.right.size());
  std::reverse(t.right.nodes.begin(), t.right.nodes.end());
  for (auto& e : t.right.arcs) {
    e.a = k - 1 - e.a;
    e.b = k - 1 - e.b;
  }
  for (auto& n : t.right.nodes)
    if (!s.left.find(n.name)) n.name = "x_" + n.name;
  return t;
}

}  // namespace

TEST(SchemeIsomorphism, LibrarySchemesAgainstThemselvesAndEachOther) {
  const std::vector<std::string> names = {"quad_subdivision",
                                          "loop_subdivision",
                                          "vertex_insertion",
                                          "vertex_insertion_folded_2",
                                          "face_triangulation",
                                          "sew2",
                                          "unsew2",
                                          "edge_deletion",
                                          "dual_vertex_insertion"};
  std::vector<RuleScheme> lib;
  for (const auto& n : names) lib.push_back(read_scheme_file(rule_file(n)));
  for (size_t a = 0; a < lib.size(); ++a) {
    EXPECT_TRUE(schemes_isomorphic(lib[a], lib[a])) << names[a];
    const auto iso = scheme_isomorphism(shuffled(lib[a]), lib[a]);
    ASSERT_TRUE(iso) << names[a];
    EXPECT_EQ(iso->right.size(), lib[a].right.size());
    for (size_t b = a + 1; b < lib.size(); ++b)
      EXPECT_FALSE(schemes_isomorphic(lib[a], lib[b])) << names[a] << " vs " << names[b];
  }
}

// A decoration or an arc changed anywhere breaks the isomorphism.
TEST(SchemeIsomorphism, AnyChangeBreaksIt) {
  const RuleScheme q = read_scheme_file(rule_file("quad_subdivision"));
  RuleScheme a = q;
  a.right.nodes[3].label = OrbitType::parse("<1,2,_>");
  EXPECT_FALSE(schemes_isomorphic(a, q));
  RuleScheme b = q;
  b.right.arcs[1].dim = 2;
  b.right.nodes[2].label = OrbitType::parse("<1,_,_>");
  EXPECT_FALSE(schemes_isomorphic(b, q));
  RuleScheme c = q;  // n1 no longer preserved-looking: swap L/R flags is impossible, but drop κ
  c.right.nodes[0].name = "m0";
  EXPECT_FALSE(schemes_isomorphic(c, q));
}

// The same rule with its positions permuted (rooted at a hook read in another order) is
// isomorphic by default, not with exact positions (docs/inference.md).
TEST(SchemeIsomorphism, UpToOneGlobalPermutationOfPositions) {
  const RuleScheme q = read_scheme_file(rule_file("quad_subdivision"));
  RuleScheme p = q;
  for (GraphScheme* g : {&p.left, &p.right})
    for (auto& n : g->nodes) {
      std::vector<int> d = n.label.dims();
      std::swap(d[0], d[2]);
      n.label = OrbitType(d);
    }
  const auto iso = scheme_isomorphism(p, q);
  ASSERT_TRUE(iso);
  EXPECT_EQ(iso->positions, (std::vector<size_t>{2, 1, 0}));
  EXPECT_FALSE(schemes_isomorphic(p, q, {.exact_positions = true}));
}
