// The fixtures of Gaide et al. 2023 on the event log, each with the dynamic detector agreeing on
// every orbit type of dimension 2: face triangulation on the house (Table 1, corrected), 2-unsewing
// twice (Fig. 7a-c), 2-sewing (Fig. 8), edge deletion inside and on the border (Fig. 9), and edge
// collapse (Figs. 1, 10, 11). The maps of the paper's figures are lost; docs/events.md describes
// the substitutes (tests/data).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "checker/events/tests/events_fixtures.hpp"

using namespace gmr;
using namespace gmr::events;
using namespace gmr::events::testing;

namespace {

struct Expected {
  OrbitEventKind kind;
  std::vector<std::string> before, after;  // representative darts by name, any dart of the orbit
};

// The house of Fig. 2: the square face BCED (darts a0..h0 = 0..7) and the roof triangle ABC
// (darts 8..13, l = 8 and m = 9 2-linked to a0 and b0).
// Two G-orbits become two H-orbits, each H-orbit holding darts of both G-orbits (Fig. 1c).
void expect_merged_and_split(const OrbitTypeLog& l) {
  EXPECT_EQ(count(l, OrbitEventKind::Merge, EventStatus::Confirmed), 2u) << describe(l.events);
  EXPECT_EQ(count(l, OrbitEventKind::Split, EventStatus::Confirmed), 2u) << describe(l.events);
  std::set<Dart> gs, hs;
  for (const auto& e : l.events) {
    if (e.kind != OrbitEventKind::Merge && e.kind != OrbitEventKind::Split) continue;
    EXPECT_EQ(e.before.size() + e.after.size(), 3u) << e.describe();
    gs.insert(e.before.begin(), e.before.end());
    hs.insert(e.after.begin(), e.after.end());
  }
  EXPECT_EQ(gs.size(), 2u);
  EXPECT_EQ(hs.size(), 2u);
}

Map house() { return io::read_map_json_file(event_data("house.json")).map; }

// A cylinder of circumference one edge and height two quads: each circle (bottom, middle, top) is a
// single edge whose two ends are one vertex. Quad k has darts 8k..8k+7: bottom side 8k, 8k+1,
// right side 8k+2, 8k+3, top side 8k+4, 8k+5, left side 8k+6, 8k+7 (8k and 8k+7 at its bottom-left
// corner, 8k+1 and 8k+2 at its bottom-right one, and so on). The right side of each quad is 2-sewn
// to its own left side (so each circle closes on one vertex); the top of the lower quad to the
// bottom of the upper one (the middle circle, darts 4, 5, 8, 9).
Map one_edge_cylinder() {
  Map g(2);
  g.add_darts(16);
  for (Dart q = 0; q < 16; q += 8) {
    for (Dart k = 0; k < 8; k += 2) g.link(0, q + k, q + k + 1);
    for (Dart k = 1; k < 8; k += 2) g.link(1, q + k, q + (k + 1) % 8);
    g.link(2, q + 2, q + 7);  // bottom-right with bottom-left
    g.link(2, q + 3, q + 6);  // top-right with top-left
  }
  g.link(2, 4, 9);  // lower quad's top-right with the upper quad's bottom-right
  g.link(2, 5, 8);
  return g;
}

// The events of 2-unsewing (kind Split) or 2-sewing back (kind Merge) the edge (1,1)-(1,2) between
// the top faces of the 2x2 grid of quads (Figs. 7a, 7b): certain on the edge (<0,2>) and two
// <2>-orbits, confirmed on the vertex (1,2); a modification of the vertex (1,1) and of the surface
// refuted.
void expect_top_edge_events(const Checked& c, OrbitEventKind kind) {
  EXPECT_EQ(count(c.log("<0,2>"), kind, EventStatus::Certain), 1u);
  EXPECT_EQ(count(c.log("<2>"), kind, EventStatus::Certain), 2u);
  EXPECT_EQ(count(c.log("<1,2>"), kind, EventStatus::Confirmed), 1u);  // (1,2)
  EXPECT_EQ(count(c.log("<1,2>"), OrbitEventKind::Modification, EventStatus::Refuted),
            1u);  // (1,1)
  EXPECT_EQ(count(c.log("<0,1,2>"), kind), 0u);
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Modification, EventStatus::Refuted), 1u);
}

}  // namespace

// Table 1: face triangulation of the square of the house at a0, all 8 orbit types, as corrected
// (the printed table names H<0>(a2) under <1>, logs the vertex B as created instead of modified and
// uses non-lowest names). Darts are named a0..h0 and x1, x2 = the copies made by n1, n2; orbits are
// compared by their lowest dart, computed here by plain traversal of G or H.
TEST(Fixtures, F1FaceTriangulationTable1) {
  Map g = house();
  const Map before = g;
  const Checked c = apply_checked(library_rule("face_triangulation"), g, {0});
  expect_oracle_agrees(c);
  const auto& app = c.logged.application;
  EXPECT_EQ(g.size(), 30u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{6, 10, 5, 1}));
  // Letter names: x0 = dart x of the square; x1, x2 = comatch of n1, n2 at x0's orbit index.
  std::map<std::string, Dart> dart;
  for (uint32_t b = 0; b < app.orbit_size(); ++b) {
    const std::string x(1, static_cast<char>('a' + app.orbit[b]));
    dart[x + "0"] = app.orbit[b];
    dart[x + "1"] = app.comatch_at(1, b);
    dart[x + "2"] = app.comatch_at(2, b);
  }
  auto low = [&](const Map& m, const std::string& o, const std::string& x) {
    const auto darts = orbit(m, OrbitType::parse(o), dart.at(x));
    return *std::min_element(darts.begin(), darts.end());
  };
  const std::map<std::string, std::vector<Expected>> table1 = {
      {"<>", {}},  // filled below: 16 creations, 8 non-modifications
      {"<0>",
       {{OrbitEventKind::Creation, {}, {"a1"}},
        {OrbitEventKind::Creation, {}, {"b1"}},
        {OrbitEventKind::Creation, {}, {"c1"}},
        {OrbitEventKind::Creation, {}, {"d1"}},
        {OrbitEventKind::Creation, {}, {"e1"}},
        {OrbitEventKind::Creation, {}, {"f1"}},
        {OrbitEventKind::Creation, {}, {"g1"}},
        {OrbitEventKind::Creation, {}, {"h1"}},
        {OrbitEventKind::NonModification, {"a0"}, {"a0"}},
        {OrbitEventKind::NonModification, {"c0"}, {"c0"}},
        {OrbitEventKind::NonModification, {"e0"}, {"e0"}},
        {OrbitEventKind::NonModification, {"g0"}, {"g0"}}}},
      {"<1>",
       {{OrbitEventKind::Creation, {}, {"a2"}},
        {OrbitEventKind::Creation, {}, {"c2"}},
        {OrbitEventKind::Creation, {}, {"e2"}},
        {OrbitEventKind::Creation, {}, {"g2"}},
        {OrbitEventKind::Split, {"a0"}, {"a0", "h0"}},
        {OrbitEventKind::Split, {"b0"}, {"b0", "c0"}},
        {OrbitEventKind::Split, {"d0"}, {"d0", "e0"}},
        {OrbitEventKind::Split, {"f0"}, {"f0", "g0"}}}},
      {"<2>",
       {{OrbitEventKind::Creation, {}, {"a1"}},
        {OrbitEventKind::Creation, {}, {"b1"}},
        {OrbitEventKind::Creation, {}, {"d1"}},
        {OrbitEventKind::Creation, {}, {"f1"}},
        {OrbitEventKind::Creation, {}, {"a2"}},
        {OrbitEventKind::Creation, {}, {"b2"}},
        {OrbitEventKind::Creation, {}, {"d2"}},
        {OrbitEventKind::Creation, {}, {"f2"}}}},
      {"<0,1>", {{OrbitEventKind::Split, {"a0"}, {"a0", "c0", "e0", "g0"}}}},
      {"<0,2>",
       {{OrbitEventKind::Creation, {}, {"a1"}},
        {OrbitEventKind::Creation, {}, {"b1"}},
        {OrbitEventKind::Creation, {}, {"d1"}},
        {OrbitEventKind::Creation, {}, {"f1"}},
        {OrbitEventKind::NonModification, {"a0"}, {"a0"}},
        {OrbitEventKind::NonModification, {"c0"}, {"c0"}},
        {OrbitEventKind::NonModification, {"e0"}, {"e0"}},
        {OrbitEventKind::NonModification, {"g0"}, {"g0"}}}},
      {"<1,2>",
       {{OrbitEventKind::Creation, {}, {"a2"}},
        {OrbitEventKind::Modification, {"a0"}, {"a0"}},
        {OrbitEventKind::Modification, {"b0"}, {"b0"}},
        {OrbitEventKind::Modification, {"d0"}, {"d0"}},
        {OrbitEventKind::Modification, {"f0"}, {"f0"}}}},
      {"<0,1,2>", {{OrbitEventKind::Modification, {"a0"}, {"a0"}}}},
  };
  for (const auto& [o, rows] : table1) {
    std::vector<Expected> want = rows;
    if (o == "<>" || o == "<2>")
      for (char x = 'a'; x <= 'h'; ++x) {
        const std::string d0 = std::string(1, x) + "0";
        want.push_back({OrbitEventKind::NonModification, {d0}, {d0}});
        if (o == "<>") {
          want.push_back({OrbitEventKind::Creation, {}, {std::string(1, x) + "1"}});
          want.push_back({OrbitEventKind::Creation, {}, {std::string(1, x) + "2"}});
        }
      }
    std::vector<OrbitEvent> expected;
    for (const auto& w : want) {
      OrbitEvent e{w.kind, OrbitType::parse(o).mask(), {}, {}, EventStatus::Observed};
      for (const auto& x : w.before) e.before.push_back(low(before, o, x));
      for (const auto& x : w.after) e.after.push_back(low(g, o, x));
      std::sort(e.after.begin(), e.after.end());
      expected.push_back(e);
    }
    EXPECT_TRUE(same_events(c.log(o).events, expected))
        << o << "\nlog:\n"
        << describe(c.log(o).events) << "expected:\n"
        << describe(expected);
  }
  // The splits on <1> and <0,1> are implicit (along n0's second position): possible, confirmed.
  EXPECT_EQ(count(c.log("<1>"), OrbitEventKind::Split, EventStatus::Confirmed), 4u);
  EXPECT_EQ(count(c.log("<0,1>"), OrbitEventKind::Split, EventStatus::Confirmed), 1u);
  EXPECT_EQ(count(c.log("<1,2>"), OrbitEventKind::Modification, EventStatus::Certain), 4u);
}

// Fig. 7a -> 7b -> 7c: 2-unsewing twice on the 2x2 grid of quads.
TEST(Fixtures, F2UnsewTwice) {
  EmbeddedMap m = io::read_off_file(event_data("quad_grid_2x2.off"));
  Map& g = m.map;
  const auto rule = library_rule("unsew2");
  // First: the edge (1,1)-(1,2) between the top faces; the surface stays connected.
  const Checked c1 = apply_checked(rule, g, {edge_dart(m, {1, 1, 0}, {1, 2, 0})});
  expect_oracle_agrees(c1);
  expect_top_edge_events(c1, OrbitEventKind::Split);
  EXPECT_EQ(cells(g), (std::vector<size_t>{10, 13, 4, 1}));
  // Second: the edge (0,1)-(1,1) between the left faces; the top-left face falls off.
  const Checked c2 = apply_checked(rule, g, {edge_dart(m, {0, 1, 0}, {1, 1, 0})});
  expect_oracle_agrees(c2);
  EXPECT_EQ(count(c2.log("<0,1,2>"), OrbitEventKind::Split, EventStatus::Confirmed), 1u);
  EXPECT_EQ(count(c2.log("<1,2>"), OrbitEventKind::Split, EventStatus::Confirmed), 2u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{12, 14, 4, 2}));
}

// Fig. 8 (7b -> 7a): 2-sewing with two hooks undoes the first unsewing.
TEST(Fixtures, F3SewTwoHooks) {
  EmbeddedMap m = io::read_off_file(event_data("quad_grid_2x2.off"));
  Map& g = m.map;
  const Map grid = g;
  const Dart a0 = edge_dart(m, {1, 1, 0}, {1, 2, 0});
  const Dart a1 = g.alpha(2, a0);
  ASSERT_TRUE(apply_checked(library_rule("unsew2"), g, {a0}).logged.application);
  const Checked c = apply_checked(library_rule("sew2"), g, {a0, a1});
  expect_oracle_agrees(c);
  expect_top_edge_events(c, OrbitEventKind::Merge);
  for (int i = 0; i <= 2; ++i) EXPECT_EQ(g.links(i), grid.links(i)) << i;  // dart for dart
}

// Fig. 9 (7c -> 7d): deleting the edge (1,0)-(1,1) between the bottom faces merges them.
TEST(Fixtures, F4EdgeDeletion) {
  EmbeddedMap m = io::read_off_file(event_data("quad_grid_2x2.off"));
  Map& g = m.map;
  const auto unsew = library_rule("unsew2");
  ASSERT_TRUE(apply_checked(unsew, g, {edge_dart(m, {1, 1, 0}, {1, 2, 0})}).logged.application);
  ASSERT_TRUE(apply_checked(unsew, g, {edge_dart(m, {0, 1, 0}, {1, 1, 0})}).logged.application);
  const Checked c =
      apply_checked(library_rule("edge_deletion"), g, {edge_dart(m, {1, 1, 0}, {1, 0, 0})});
  expect_oracle_agrees(c);
  EXPECT_EQ(count(c.log("<0,2>"), OrbitEventKind::Deletion, EventStatus::Certain), 1u);
  EXPECT_EQ(count(c.log("<1>"), OrbitEventKind::Merge, EventStatus::Confirmed), 2u);
  EXPECT_EQ(count(c.log("<0,1>"), OrbitEventKind::Merge, EventStatus::Confirmed), 1u);
  EXPECT_EQ(count(c.log("<0,1>"), OrbitEventKind::Split), 0u);
  EXPECT_EQ(count(c.log("<1,2>"), OrbitEventKind::Modification), 2u);
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Modification), 1u);
  EXPECT_EQ(g.size(), 28u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{12, 13, 3, 2}));
}

// The counterexample to "a complete implicit merge is certain" (§3.3, Table 1): deleting a border
// edge, whose hook orbit has 2 darts (2-loops), rewires n1 onto itself: the <1> pattern orbit is
// complete and implicitly merged, but the two <1>-orbits stay apart (modified).
TEST(Fixtures, F4bBorderEdgeDeletionIsNoMerge) {
  EmbeddedMap m = io::read_off_file(event_data("quad_grid_2x2.off"));
  Map& g = m.map;
  const auto rule = library_rule("edge_deletion");
  const StaticEvents st = analyse(rule, {OrbitType{1}});
  bool complete_implicit_merge = false;
  for (const auto& e : st.orbits[0].events)
    complete_implicit_merge |=
        e.kind == PatternEventKind::ImplicitMerge && st.orbits[0].left.complete[e.left[0]];
  EXPECT_TRUE(complete_implicit_merge);
  const Checked c = apply_checked(rule, g, {edge_dart(m, {0, 0, 0}, {1, 0, 0})});
  expect_oracle_agrees(c);
  EXPECT_EQ(count(c.log("<1>"), OrbitEventKind::Merge), 0u);
  EXPECT_EQ(count(c.log("<1>"), OrbitEventKind::Modification, EventStatus::Refuted), 2u);
  EXPECT_EQ(count(c.log("<0,1>"), OrbitEventKind::Merge), 0u);
  EXPECT_EQ(count(c.log("<0,1>"), OrbitEventKind::Modification), 1u);
}

// Figs. 1, 10, 11: edge collapse. On the triangulated grid, (1,1)-(1,0) merges two vertices (no
// split); then S1-(1,2), whose ends are both on the border, merges them and splits the result
// (Fig. 1c), which disconnects the disk (a G-map has no pinched vertex).
TEST(Fixtures, F5EdgeCollapseMergeThenMergeAndSplit) {
  EmbeddedMap m = io::read_off_file(event_data("triangle_grid_2x2.off"));
  Map& g = m.map;
  EXPECT_EQ(cells(g), (std::vector<size_t>{9, 16, 8, 1}));
  const auto rule = library_rule("edge_collapse");
  const Checked c1 = apply_checked(rule, g, {edge_dart(m, {1, 1, 0}, {1, 0, 0})});
  expect_oracle_agrees(c1);
  EXPECT_EQ(count(c1.log("<1,2>"), OrbitEventKind::Merge, EventStatus::Confirmed), 1u);
  EXPECT_EQ(count(c1.log("<1,2>"), OrbitEventKind::Split), 0u);
  EXPECT_EQ(count(c1.log("<1>"), OrbitEventKind::Merge), 2u);
  EXPECT_EQ(count(c1.log("<0,1>"), OrbitEventKind::Modification), 2u);
  EXPECT_EQ(count(c1.log("<0,1,2>"), OrbitEventKind::Modification), 1u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{8, 15, 8, 1}));
  const Checked c2 = apply_checked(rule, g, {edge_dart(m, {1, 1, 0}, {1, 2, 0})});
  expect_oracle_agrees(c2);
  // Two H-vertices, each holding parts of both G-vertices: each G-vertex is split in two, each
  // H-vertex merges two.
  expect_merged_and_split(c2.log("<1,2>"));
  EXPECT_EQ(count(c2.log("<0,1,2>"), OrbitEventKind::Split, EventStatus::Confirmed), 1u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{8, 14, 8, 2}));
}

// Fig. 1e on a cylinder: collapsing an edge between the two border circles merges its two ends and
// splits the result; the surface stays connected.
TEST(Fixtures, F5EdgeCollapseOnCylinder) {
  EmbeddedMap m = io::read_off_file(event_data("cylinder_4.off"));
  Map& g = m.map;
  EXPECT_EQ(cells(g), (std::vector<size_t>{8, 16, 8, 1}));
  const Checked c =
      apply_checked(library_rule("edge_collapse"), g, {edge_dart(m, {1, 0, 0}, {1, 0, 1})});
  expect_oracle_agrees(c);
  expect_merged_and_split(c.log("<1,2>"));
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Split), 0u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{8, 15, 8, 1}));
}

// Fig. 1e, "no vertex merging at all, but only a split": the two ends of the collapsed edge must
// already be one vertex (else the collapse merges them), i.e. the edge is a loop of the vertex
// graph. On a cylinder this is an edge closing a circle on itself: collapsing the middle circle of
// the one-edge cylinder pinches the cylinder there, and a G-map has no pinched vertex, so its
// vertex is split into the lower and the upper one, without any merge; the two halves fall apart.
TEST(Fixtures, F5EdgeCollapseSplitOnlyOnCylinder) {
  Map g = one_edge_cylinder();
  EXPECT_EQ(cells(g), (std::vector<size_t>{3, 5, 2, 1}));
  const auto vertex = orbit(g, OrbitType{1, 2}, 4);
  EXPECT_NE(std::find(vertex.begin(), vertex.end(), Dart{5}),
            vertex.end());  // both ends: one vertex
  const auto rule = library_rule("edge_collapse");
  const Checked c = apply_checked(rule, g, {4});
  expect_oracle_agrees(c);
  const OrbitTypeLog& v = c.log("<1,2>");
  EXPECT_EQ(count(v, OrbitEventKind::Merge), 0u) << describe(v.events);
  ASSERT_EQ(count(v, OrbitEventKind::Split, EventStatus::Confirmed), 1u) << describe(v.events);
  for (const auto& e : v.events) {
    if (e.kind == OrbitEventKind::Split) {
      EXPECT_EQ(e.after.size(), 2u) << e.describe();
    }
  }
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Split, EventStatus::Confirmed), 1u);
  EXPECT_EQ(cells(g), (std::vector<size_t>{4, 4, 2, 2}));
}

// Def. 3.4.2 / §3.4.3 decide modification on the pattern: L<0,1>(n0) of swap_0_1 turns its
// implicit 1-links into 0-links and its 0-loop into a 1-loop, a modification. On a free dart the
// hook orbit is a single dart, the implicit 1-link a 1-loop, and H = G: the orbit is not modified,
// which the log finds by comparing the matched darts' links (status refuted). On two 1-linked darts
// the modification happens.
TEST(Fixtures, StaticModificationRefutedOnALoop) {
  const auto rule = io::read_scheme_file(event_data("swap_0_1.json"));
  const StaticEvents st = analyse(rule, {OrbitType{0, 1}});
  ASSERT_EQ(st.orbits[0].events.size(), 1u);
  EXPECT_EQ(st.orbits[0].events[0].kind, PatternEventKind::Modification);
  Map dart = io::read_map_json_file(event_data("free_dart.json")).map;
  const Checked c1 = apply_checked(rule, dart, {0});
  expect_oracle_agrees(c1);
  EXPECT_EQ(count(c1.log("<0,1>"), OrbitEventKind::NonModification, EventStatus::Refuted), 1u);
  EXPECT_EQ(count(c1.log("<0,1>"), OrbitEventKind::Modification), 0u);
  Map corner = io::read_map_json_file(event_data("one_corner.json")).map;
  const Checked c2 = apply_checked(rule, corner, {0});
  expect_oracle_agrees(c2);
  EXPECT_EQ(count(c2.log("<0,1>"), OrbitEventKind::Modification, EventStatus::Certain), 1u);
}
