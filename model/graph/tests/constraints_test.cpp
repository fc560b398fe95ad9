// The three local constraints on hand-made D-graphs (thesis Defs. 29–32): each violation detected
// and located (node, dimension(s), path).
#include "model/graph/constraints.hpp"

#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::graph;

static bool has(const std::vector<ConstraintViolation>& vs, Constraint k, Node v, int i,
                int j = -1) {
  for (const auto& c : vs)
    if (c.constraint == k && c.at == v.index() && c.i == i && c.j == j) return true;
  return false;
}

TEST(Constraints, GMapAsDGraphSatisfiesAll) {
  DGraph dg = to_dgraph(make_cube(2));
  EXPECT_TRUE(check_map_constraints(dg, 2, MapKind::GMap).empty());
  DGraph s = to_dgraph(make_stacked_cubes());
  EXPECT_TRUE(check_map_constraints(s, 3, MapKind::GMap).empty());
}

TEST(Constraints, IncidentArcsMissingAndDuplicate) {
  DGraph g;
  Node a = g.add_node("a"), b = g.add_node("b"), c = g.add_node("c");
  g.add_link(a, b, 0);
  g.add_arc(c, c, 0);
  g.add_arc(a, c, 0);  // a now has two outgoing 0-arcs, c two incoming
  auto va = check_incident_arcs(g, a, 0);
  ASSERT_EQ(va.size(), 1u);
  EXPECT_EQ(va[0].message, "2 outgoing 0-arcs");
  EXPECT_EQ(va[0].path, (std::vector<uint32_t>{a.index(), b.index(), c.index()}));
  auto vc = check_incident_arcs(g, c, 0);
  ASSERT_EQ(vc.size(), 1u);
  EXPECT_EQ(vc[0].message, "2 incoming 0-arcs");
  auto vb1 = check_incident_arcs(g, b, 1);
  EXPECT_EQ(vb1.size(), 2u);  // no outgoing and no incoming 1-arc
  EXPECT_NE(to_text(vb1[0], g).find("at node b"), std::string::npos);
}

TEST(Constraints, NonOrientationNamesTheArc) {
  DGraph g;
  Node a = g.add_node("a"), b = g.add_node("b");
  g.add_arc(a, b, 2);
  g.add_arc(b, a, 1);
  auto v = check_non_orientation(g, a, 2);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].path, (std::vector<uint32_t>{a.index(), b.index()}));
  EXPECT_NE(v[0].message.find("a->b"), std::string::npos);
  EXPECT_EQ(check_non_orientation(g, b, 2).size(), 1u);  // incoming arc without reverse
  EXPECT_TRUE(check_non_orientation(g, a, 0).empty());
}

TEST(Constraints, CycleBrokenOnOneNode) {
  // Two darts a,b 0-linked; a 2-linked to c, b 2-free: 0202 from a: a-0->b-2->b-0->a-2->c != a.
  DGraph g;
  Node a = g.add_node("a"), b = g.add_node("b"), c = g.add_node("c"), d = g.add_node("d");
  g.add_link(a, b, 0);
  g.add_link(c, d, 0);
  g.add_link(a, c, 2);
  g.add_arc(b, b, 2);
  g.add_arc(d, d, 2);
  for (Node v : {a, b, c, d}) g.add_arc(v, v, 1);
  auto va = check_cycle(g, a, 0, 2);
  ASSERT_EQ(va.size(), 1u);
  EXPECT_EQ(va[0].path.size(), 5u);
  EXPECT_EQ(va[0].path.front(), a.index());
  EXPECT_NE(va[0].path.back(), a.index());
  auto all = check_map_constraints(g, 2, MapKind::GMap);
  EXPECT_TRUE(has(all, Constraint::Cycle, a, 0, 2));
  EXPECT_TRUE(has(all, Constraint::Cycle, d, 0, 2));
  for (const auto& cv : all) EXPECT_EQ(cv.constraint, Constraint::Cycle);
}

TEST(Constraints, LabelOutsideDimensionSet) {
  DGraph g = to_dgraph(make_polygon(2, 2));
  g.add_arc(Node(0), Node(0), 5);
  auto all = check_map_constraints(g, 2, MapKind::GMap);
  ASSERT_FALSE(all.empty());
  EXPECT_NE(all[0].message.find("label 5"), std::string::npos);
}

TEST(Constraints, OMapDimensionOneMayBeOriented) {
  Map o = orient(make_cube(2));
  DGraph dg = to_dgraph(o);
  EXPECT_TRUE(check_map_constraints(dg, 2, MapKind::OMap).empty());
  // As a G-map over 1..2 the oriented 1-arcs break non-orientation.
  bool found = false;
  for (const auto& c : check_map_constraints(dg, 2, MapKind::GMap))
    if (c.constraint == Constraint::NonOrientation && c.i == 1) found = true;
  EXPECT_TRUE(found);
}

TEST(Constraints, ToGMapRejectsMissingArcWithLocation) {
  DGraph g;
  g.add_node("x");
  try {
    to_map(g, 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidMap);
    EXPECT_EQ(e.location(), "node x");
  }
}
