// DOT text of rules (model/io_rule_dot.hpp): L and R clusters, colours per dimension, one edge per
// link, κ arcs on request, node roles, scheme labels "n0 <_,1,2>", double-bordered hooks, loops.
#include "model/draw/rule_dot.hpp"

#include <gtest/gtest.h>

#include "model/rule_io/rule_json.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/count_occurrences.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::draw;

namespace {

using gmr::testing::count_occurrences;

std::string source(const std::string& rel) { return gmr::testing::source_path(rel); }

// 2-sew of two 2-free edges a–0–b and c–0–d, written as a concrete G-map rule.
Rule sew_rule() {
  DGraph L, R;
  for (DGraph* g : {&L, &R})
    for (const char* n : {"a", "b", "c", "d"}) g->add_node(n);
  for (DGraph* g : {&L, &R}) {
    g->add_link(Node(0), Node(1), 0);
    g->add_link(Node(2), Node(3), 0);
  }
  L.add_arc(Node(0), Node(0), 2);
  L.add_arc(Node(1), Node(1), 2);
  L.add_arc(Node(2), Node(2), 2);
  L.add_arc(Node(3), Node(3), 2);
  R.add_link(Node(0), Node(2), 2);
  R.add_link(Node(1), Node(3), 2);
  return Rule(L, R, 2, MapKind::GMap, "sew");
}

}  // namespace

TEST(IoRuleDot, ConcreteRuleSideBySide) {
  const Rule r = sew_rule();
  const std::string dot = to_dot(r);
  EXPECT_EQ(dot.rfind("digraph \"sew\" {", 0), 0u) << dot;
  EXPECT_EQ(count_occurrences(dot, "subgraph cluster_L {"), 1u);
  EXPECT_EQ(count_occurrences(dot, "subgraph cluster_R {"), 1u);
  EXPECT_NE(dot.find("L0 [label=\"a\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("R3 [label=\"d\"]"), std::string::npos) << dot;
  // Two 0-links per side, one undirected edge each; four deleted 2-loops in L, two added 2-links in
  // R.
  EXPECT_EQ(count_occurrences(dot, "[color=black, dir=none]"), 4u) << dot;
  EXPECT_EQ(count_occurrences(dot, "[color=blue, penwidth=2.5, dir=none]"), 6u) << dot;
  EXPECT_NE(dot.find("L0 -> L0 [color=blue"), std::string::npos);
  EXPECT_EQ(count_occurrences(dot, "color=pink"), 0u);
  RuleDotOptions opt;
  opt.kappa = true;
  const std::string k = to_dot(r, opt);
  EXPECT_EQ(count_occurrences(k, "color=pink, style=dashed"), 4u) << k;
  EXPECT_NE(k.find("L2 -> R2 [color=pink"), std::string::npos);
}

TEST(IoRuleDot, NodeRolesAndDirectedArcs) {
  DGraph L, R;
  L.add_node("a");
  L.add_node("gone");
  L.add_link(Node(0), Node(1), 1);
  R.add_node("a");
  R.add_node("new");
  R.add_arc(Node(0), Node(1), 1);  // unpaired: drawn directed
  R.add_arc(Node(1), Node(0), 3);
  const Rule r(L, R, 3);
  const std::string dot = to_dot(r);
  EXPECT_NE(dot.find("L1 [label=\"gone\", style=\"dashed\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("R1 [label=\"new\", style=\"bold\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("R0 -> R1 [color=red, penwidth=2.5]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("R1 -> R0 [color=green, penwidth=2.5]"), std::string::npos) << dot;
}

TEST(IoRuleDot, SchemeLabelsHooksLoops) {
  const RuleScheme sew = read_scheme_file(source("tools/data/rules/sew2.json"));
  const std::string dot = to_dot(sew);
  EXPECT_NE(dot.find("L0 [label=\"n0 <0>\", peripheries=2]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("L1 [label=\"n1 <0>\", peripheries=2]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("R0 [label=\"n0 <0>\"]"), std::string::npos) << dot;
  EXPECT_EQ(count_occurrences(dot, "peripheries=2"), 2u);  // hooks only, on L
  EXPECT_NE(dot.find("L0 -> L0 [color=blue, penwidth=2.5]"), std::string::npos)
      << dot;  // deleted loop
  EXPECT_NE(dot.find("R0 -> R1 [color=blue, penwidth=2.5]"), std::string::npos)
      << dot;  // added arc

  const RuleScheme quad = read_scheme_file(source("tools/data/rules/quad_subdivision.json"));
  const std::string q = to_dot(quad);
  EXPECT_NE(q.find("label=\"n0 <0,1,2>\", peripheries=2"), std::string::npos) << q;
  EXPECT_NE(q.find("R0 [label=\"n0 <_,1,2>\"]"), std::string::npos) << q;
  EXPECT_NE(q.find("R3 [label=\"n3 <2,1,_>\", style=\"bold\"]"), std::string::npos) << q;
  EXPECT_NE(q.find("R1 -> R2 [color=red, penwidth=2.5]"), std::string::npos) << q;
  EXPECT_NE(q.find("R0 -> R1 [color=black, penwidth=2.5]"), std::string::npos) << q;
}

TEST(IoRuleDot, Highlights) {
  const RuleScheme sew = read_scheme_file(source("tools/data/rules/sew2.json"));
  RuleDotOptions opt;
  opt.highlights = {{graph::Side::R, "n1", "X-code", "a message", true},
                    {std::nullopt, "n0", "W-code", "careful", false}};
  const std::string dot = to_dot(sew, opt);
  EXPECT_NE(dot.find("R1 [label=\"n1 <0>\", fillcolor=\"#ff9c9c\", tooltip=\"X-code: a message\", "
                     "style=\"filled\"]"),
            std::string::npos)
      << dot;
  EXPECT_NE(
      dot.find("R1_note [shape=note, fontsize=8, fontcolor=darkred, color=gray, label=\"X-code\"]"),
      std::string::npos);
  EXPECT_NE(dot.find("R1 -> R1_note [style=dotted"), std::string::npos);
  EXPECT_EQ(dot.find("L1 [label=\"n1 <0>\", peripheries=2, fill"), std::string::npos)
      << dot;                                                             // R only
  EXPECT_EQ(count_occurrences(dot, "fillcolor=\"#ffd58a\""), 2u) << dot;  // n0 on both sides
}
