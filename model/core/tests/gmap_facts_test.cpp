// Facts from the papers about standard objects.
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"

using namespace gmr;

TEST(PaperFacts, StackedCubesLinkCounts) {
  // Inference paper §3.3 / thesis Ch. 6: 96 darts, 48 0-links, 48 1-links, 48 2-links, 88 3-links.
  Map g = make_stacked_cubes();
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(g.size(), 96u);
  EXPECT_EQ(g.count_links(0), 48u);
  EXPECT_EQ(g.count_links(1), 48u);
  EXPECT_EQ(g.count_links(2), 48u);
  EXPECT_EQ(g.count_links(3), 88u);
  EXPECT_EQ(count_cells(g, 0), 12u);
  EXPECT_EQ(count_cells(g, 1), 20u);
  EXPECT_EQ(count_cells(g, 2), 11u);
  EXPECT_EQ(count_cells(g, 3), 2u);
  EXPECT_EQ(count_components(g), 1u);
}

TEST(PaperFacts, CubeSurface) {
  Map g = make_cube(2);
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(g.size(), 48u);
  EXPECT_EQ(count_cells(g, 0), 8u);
  EXPECT_EQ(count_cells(g, 1), 12u);
  EXPECT_EQ(count_cells(g, 2), 6u);
  EXPECT_EQ(euler_characteristic(g), 2);
  EXPECT_TRUE(is_closed(g));
}

TEST(PaperFacts, CellOrbitTypes) {
  // Inference paper §3.3: 2D vertex <1,2>, edge <0,2>, face <0,1>; 3D vertex <1,2,3>, edge
  // <0,2,3>, face <0,1,3>, volume <0,1,2>.
  Map g2(2), g3(3);
  EXPECT_EQ(cell_type(g2, 0).str(), "<1,2>");
  EXPECT_EQ(cell_type(g2, 1).str(), "<0,2>");
  EXPECT_EQ(cell_type(g2, 2).str(), "<0,1>");
  EXPECT_EQ(cell_type(g3, 0).str(), "<1,2,3>");
  EXPECT_EQ(cell_type(g3, 1).str(), "<0,2,3>");
  EXPECT_EQ(cell_type(g3, 2).str(), "<0,1,3>");
  EXPECT_EQ(cell_type(g3, 3).str(), "<0,1,2>");
  // On the stacked cubes: a vertex of the shared face has 12 darts (3 edges x 2 faces x 2
  // volumes), a half-face <0,1> has 8 darts, a volume 48.
  Map s = make_stacked_cubes();
  EXPECT_EQ(orbit(s, OrbitType{0, 1, 2}, 0).size(), 48u);
  EXPECT_EQ(orbit(s, OrbitType{0, 1}, 0).size(), 8u);
}
