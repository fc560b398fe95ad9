// Checked sewing (CGAL/Moka semantics) refuses every sew that would break validity.
#include "model/core/sew.hpp"

#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"

using namespace gmr;

static Map two_squares() {
  Map g = make_polygon(4, 2);
  const Dart base = g.add_darts(8);
  Map h = make_polygon(4, 2);
  for (int i = 0; i <= 1; ++i)
    for (Dart d = 0; d < 8; ++d) g.set_alpha(i, base + d, base + h.alpha(i, d));
  return g;
}

TEST(Sew, TwoSewGluesAnEdge) {
  Map g = two_squares();
  EXPECT_EQ(sew_orbit_type(g, 2).str(), "<0>");
  sew(g, 2, 0, 8);
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(g.alpha(2, 0), 8u);
  EXPECT_EQ(g.alpha(2, 1), 9u);  // propagated along <0>
  EXPECT_EQ(count_cells(g, 1), 7u);
  EXPECT_EQ(count_cells(g, 0), 6u);
  unsew(g, 2, 9);
  EXPECT_TRUE(g.is_free(2, 0));
  EXPECT_TRUE(g.is_free(2, 1));
  EXPECT_TRUE(is_valid(g));
}

TEST(Sew, RefusesNonFreeAndSelf) {
  Map g = two_squares();
  sew(g, 2, 0, 8);
  std::string why;
  EXPECT_FALSE(is_sewable(g, 2, 0, 2, &why));
  EXPECT_NE(why.find("not 2-free"), std::string::npos);
  try {
    sew(g, 2, 1, 3);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Sew);
  }
  EXPECT_FALSE(is_sewable(g, 2, 3, 3));
  EXPECT_THROW(unsew(g, 2, 5), Error);  // already free
}

TEST(Sew, RefusesNonIsomorphicOrbits) {
  // 3-sew of a square face onto a triangle face: the <0,1>-orbits differ.
  Map g(3);
  Map sq = make_polygon(4, 3), tr = make_polygon(3, 3);
  g.add_darts(14);
  for (int i = 0; i <= 1; ++i) {
    for (Dart d = 0; d < 8; ++d) g.set_alpha(i, d, sq.alpha(i, d));
    for (Dart d = 0; d < 6; ++d) g.set_alpha(i, 8 + d, 8 + tr.alpha(i, d));
  }
  std::string why;
  EXPECT_FALSE(is_sewable(g, 3, 0, 8, &why));
  EXPECT_NE(why.find("not isomorphic"), std::string::npos);
  EXPECT_TRUE(is_valid(g));
  // Two squares do 3-sew, and the whole face is linked.
  Map h(3);
  h.add_darts(16);
  for (int i = 0; i <= 1; ++i)
    for (Dart d = 0; d < 8; ++d) {
      h.set_alpha(i, d, sq.alpha(i, d));
      h.set_alpha(i, 8 + d, 8 + sq.alpha(i, d));
    }
  sew(h, 3, 0, 8);
  EXPECT_TRUE(is_valid(h));
  for (Dart d = 0; d < 8; ++d) EXPECT_FALSE(h.is_free(3, d));
}

TEST(Sew, OneSewClosesAPolygon) {
  // An open polyline of 3 edges 1-sewn at its ends makes a triangle.
  Map g(2);
  g.add_darts(6);
  g.link(0, 0, 1);
  g.link(1, 1, 2);
  g.link(0, 2, 3);
  g.link(1, 3, 4);
  g.link(0, 4, 5);
  EXPECT_EQ(sew_orbit_type(g, 1).str(), "<>");  // wait: (0..2)\{0,1,2} is empty
  sew(g, 1, 5, 0);
  EXPECT_TRUE(is_valid(g));
  EXPECT_EQ(count_cells(g, 2), 1u);
  EXPECT_EQ(count_cells(g, 0), 3u);
}
