// Rule schemes: structure, instantiation (Defs. 88–89) and the application engine.
#include "model/scheme/scheme_engine.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/scheme/scheme_instantiation.hpp"
#include "model/scheme/tests/scheme_fixtures.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::scheme;
using namespace gmr::fixtures;

TEST(RuleScheme, RolesAndStructure) {
  RuleScheme r = quad_subdivision();
  EXPECT_NO_THROW(r.validate_structure());
  EXPECT_EQ(r.role_left(0), NodeRole::Preserved);
  EXPECT_EQ(r.role_right(1), NodeRole::Added);
  EXPECT_EQ(r.right.count_arcs(1, 2), 1u);
  EXPECT_EQ(r.right.count_arcs(1, 0), 1u);
  EXPECT_EQ(node_label_text(r.right.nodes[0]), "n0 <_,1,2>");
  RuleScheme bad = r;
  bad.right.nodes[1].label = ot("<_,2>");
  EXPECT_THROW(bad.validate_structure(), Error);
  bad = r;
  bad.right.arcs.push_back({0, 1, 3});
  EXPECT_THROW(bad.validate_structure(), Error);
  bad = r;
  bad.hooks = {"zz"};
  EXPECT_THROW(bad.validate_structure(), Error);
  bad = r;
  bad.right.add_node("n0", ot("<0,1,2>"));
  EXPECT_THROW(bad.validate_structure(), Error);
  std::vector<uint32_t> comp;
  EXPECT_EQ(sew2().left.components(comp), 2u);
  EXPECT_EQ(sew2().right.components(comp), 1u);
}

TEST(Instantiation, NodeArcAndRule) {
  Map cube = make_cube(2);
  OrbitGraph O = orbit_graph(cube, ot("<0,1>"), 0);  // a quad face
  ASSERT_EQ(O.size(), 8u);
  // Def. 88: <0,1> -> <_,2> keeps only the 1-links, relabelled 2.
  SchemeNode v{"n1", ot("<_,2>"), {}};
  InstantiatedGraph iv = instantiate_node(v, O);
  EXPECT_EQ(iv.graph.num_nodes(), 8u);
  EXPECT_EQ(iv.graph.num_arcs(), 8u);  // 4 links, two arcs each
  for (uint32_t b = 0; b < 8; ++b) {
    EXPECT_EQ(iv.graph.successors(iv.at(0, b), 2).size(), 1u);
    EXPECT_TRUE(iv.graph.successors(iv.at(0, b), 0).empty());
  }
  EXPECT_EQ(iv.graph.name(iv.at(0, 0)), "0_n1");
  // Discrete scheme and arcs.
  GraphScheme gs;
  gs.add_node("a", ot("<0,_>"));
  gs.add_node("b", ot("<_,_>"));
  gs.add_arc("a", "b", 1);
  InstantiatedGraph ig = instantiate_nodes(gs, O);
  EXPECT_EQ(ig.graph.num_nodes(), 16u);
  EXPECT_EQ(ig.graph.num_arcs(), 8u);
  instantiate_arc(gs.arcs[0], O, ig);
  EXPECT_EQ(ig.graph.num_arcs(), 24u);
  EXPECT_EQ(ig.graph.successors(ig.at(0, 3), 1), std::vector<Node>{ig.at(1, 3)});
  // F9 counts: L = N nodes / 3N arcs, R = 4N nodes / 12N arcs (on a whole cube, N = 48).
  OrbitGraph whole = orbit_graph(cube, ot("<0,1,2>"), 0);
  InstantiatedRule ir = instantiate_sides(quad_subdivision(), whole);
  EXPECT_EQ(ir.left.graph.num_nodes(), 48u);
  EXPECT_EQ(ir.left.graph.num_arcs(), 3u * 48);
  EXPECT_EQ(ir.right.graph.num_nodes(), 4u * 48);
  EXPECT_EQ(ir.right.graph.num_arcs(), 12u * 48);
  EXPECT_THROW(instantiate_node(SchemeNode{"x", ot("<0>"), {}}, whole), Error);
}

TEST(Engine, QuadSubdivisionOfCube) {
  Map g = make_cube(2);
  SchemeApplication a = scheme::apply(SchemeEngine(quad_subdivision()), g, {0});
  ASSERT_TRUE(a.applied) << a.why;
  EXPECT_EQ(g.size(), 192u);
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(count_all_cells(g), (std::vector<size_t>{26, 48, 24}));
  EXPECT_EQ(a.orbit_size(), 48u);
  EXPECT_EQ(a.darts_added, 144u);
  EXPECT_EQ(a.comatch_at(0, 5), a.orbit[5]);  // preserved node keeps its darts
}

TEST(Engine, VertexInsertionFreeAndSewnEdge) {
  Map e = make_free_edge(2);
  auto [h, a] = scheme::apply(SchemeEngine(vertex_insertion()), std::as_const(e), {0});
  ASSERT_TRUE(a.applied) << a.why;
  EXPECT_EQ(h.size(), 4u);
  EXPECT_TRUE(is_valid(h));
  Map cube = make_cube(2);
  auto [h2, a2] = scheme::apply(SchemeEngine(vertex_insertion()), std::as_const(cube), {0});
  ASSERT_TRUE(a2.applied);
  EXPECT_EQ(h2.size(), 52u);
  EXPECT_EQ(count_all_cells(h2), (std::vector<size_t>{9, 13, 6}));
  EXPECT_TRUE(is_valid(h2));
}

TEST(Engine, SewTwoHooksAndNotApplicable) {
  Map g = make_polygon(3, 2);
  Map t2 = make_polygon(3, 2);
  // Two disjoint triangles in one map: copy t2's darts after g's.
  const Dart off = g.add_darts(t2.size());
  for (Dart d = 0; d < t2.size(); ++d)
    for (int i = 0; i <= 2; ++i) g.set_alpha(i, off + d, off + t2.alpha(i, d));
  ASSERT_TRUE(is_valid(g));
  auto [h, a] = scheme::apply(SchemeEngine(sew2()), std::as_const(g), {0, off});
  ASSERT_TRUE(a.applied) << a.why;
  EXPECT_TRUE(is_valid(h));
  EXPECT_EQ(h.alpha(2, 0), off);
  EXPECT_EQ(h.alpha(2, g.alpha(0, 0)), g.alpha(0, off));
  // Sewing again: the 2-loops of L are missing.
  auto [h3, a3] = scheme::apply(SchemeEngine(sew2()), std::as_const(h), {0, off});
  EXPECT_FALSE(a3.applied);
  EXPECT_EQ(a3.reason, NotApplicableReason::MissingExplicitArc);
  EXPECT_NE(a3.why.find("not applicable, because"), std::string::npos);
  // Same orbit for both hooks: not injective.
  auto [h4, a4] = scheme::apply(SchemeEngine(sew2()), std::as_const(g), {0, g.alpha(0, 0)});
  EXPECT_FALSE(a4.applied);
  EXPECT_EQ(a4.reason, NotApplicableReason::NotInjective);
  // Wrong number of hook darts: usage error.
  EXPECT_THROW(scheme::apply(SchemeEngine(sew2()), std::as_const(g), {0}), Error);
  // Quad rule on a 3-G-map: usage error.
  EXPECT_THROW(scheme::apply(SchemeEngine(quad_subdivision()), make_cube(3), {0}), Error);
}

TEST(Engine, HookOrbitsNotIsomorphic) {
  RuleScheme r = sew2();
  r.orbit = ot("<0,1>");
  for (auto* side : {&r.left, &r.right})
    for (auto& n : side->nodes) n.label = ot("<0,1>");
  // r now sews two faces along all their edges: a triangle and a quad are not isomorphic.
  Map g = make_polygon(3, 2);
  Map q = make_polygon(4, 2);
  const Dart off = g.add_darts(q.size());
  for (Dart d = 0; d < q.size(); ++d)
    for (int i = 0; i <= 2; ++i) g.set_alpha(i, off + d, off + q.alpha(i, d));
  auto [h, a] = scheme::apply(SchemeEngine(r), std::as_const(g), {0, off});
  EXPECT_FALSE(a.applied);
  EXPECT_EQ(a.reason, NotApplicableReason::HookOrbitsNotIsomorphic);
  EXPECT_EQ(h.size(), g.size());
}

TEST(Engine, NotCombinatorialScheme) {
  RuleScheme r = vertex_insertion();
  r.right.nodes[1].label = ot("<_,2>");  // added node without 1-arc
  Map e = make_free_edge(2);
  auto [h, a] = scheme::apply(SchemeEngine(r), std::as_const(e), {0});
  EXPECT_FALSE(a.applied);
  EXPECT_EQ(a.reason, NotApplicableReason::NotCombinatorial);
  EXPECT_NE(a.why.find("added node n1"), std::string::npos);
}
