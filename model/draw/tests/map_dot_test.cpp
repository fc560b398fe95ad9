// DOT text of maps (model/io_dot.hpp): one edge per link coloured per dimension, loops on request,
// O-map beta_1 as directed arcs, non-reciprocated links dashed.
#include "model/draw/map_dot.hpp"

#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/testing/count_occurrences.hpp"

using namespace gmr;
using namespace gmr::draw;

using gmr::testing::count_occurrences;

TEST(IoDot, ColoursPerDimension) {
  EXPECT_EQ(dimension_colour(0), "black");
  EXPECT_EQ(dimension_colour(1), "red");
  EXPECT_EQ(dimension_colour(2), "blue");
  EXPECT_EQ(dimension_colour(3), "green");
  EXPECT_EQ(dimension_colour(4), "orange");
  EXPECT_EQ(dimension_colour(9), "gray");
}

TEST(IoDot, StackedCubesOneEdgePerLink) {
  const Map g = make_stacked_cubes();
  const std::string dot = to_dot(g);
  EXPECT_EQ(dot.rfind("graph \"gmap\" {", 0), 0u);
  // 48 0-links, 48 1-links, 48 2-links; 88 3-links of which 80 are loops (not drawn by default).
  EXPECT_EQ(count_occurrences(dot, "[color=black]"), 48u);
  EXPECT_EQ(count_occurrences(dot, "[color=red]"), 48u);
  EXPECT_EQ(count_occurrences(dot, "[color=blue]"), 48u);
  EXPECT_EQ(count_occurrences(dot, "[color=green]"), 8u);
  EXPECT_EQ(count_occurrences(dot, " -- "), 152u);
  EXPECT_EQ(count_occurrences(dot, " -> "), 0u);
  DotOptions opt;
  opt.loops = true;
  const std::string with_loops = to_dot(g, opt);
  EXPECT_EQ(count_occurrences(with_loops, "[color=green]"), 88u);
  EXPECT_NE(with_loops.find("  0 -- 0 [color=green];"), std::string::npos);
}

TEST(IoDot, OMapBetaOneIsDirected) {
  const Map o = orient(make_cube());  // 24 darts, beta_1 a permutation, beta_2 an involution
  const std::string dot = to_dot(o);
  EXPECT_EQ(dot.rfind("digraph", 0), 0u);
  EXPECT_EQ(count_occurrences(dot, "[color=red]"), 24u);
  EXPECT_EQ(count_occurrences(dot, "[color=blue, dir=none]"), 12u);
}

TEST(IoDot, NonReciprocatedLinksAreDashedArrows) {
  Map g(1);
  g.add_darts(3);
  g.set_alpha(0, 0, 1);  // 0 -> 1 but 1 -> 2
  g.set_alpha(0, 1, 2);
  g.set_alpha(0, 2, 1);
  const std::string dot = to_dot(g);
  EXPECT_NE(dot.find("  0 -- 1 [color=black, style=dashed, dir=forward];"), std::string::npos)
      << dot;
  EXPECT_NE(dot.find("  1 -- 2 [color=black];"), std::string::npos) << dot;
  EXPECT_EQ(count_occurrences(dot, " -- "), 2u);
}

TEST(IoDot, GraphNameIsQuoted) {
  DotOptions opt;
  opt.name = "my \"map\"";
  EXPECT_EQ(to_dot(make_free_edge(), opt).rfind("graph \"my \\\"map\\\"\" {", 0), 0u);
}
