// Validity reports every violation with its location (dart, dimensions, path).
#include <gtest/gtest.h>

#include "model/core/builders.hpp"
#include "model/core/validity.hpp"

using namespace gmr;

TEST(Validity, BrokenInvolutionReported) {
  Map g = make_cube(2);
  const Dart d = 0, e = g.alpha(2, 0);
  g.set_alpha(2, d, g.alpha(0, d));  // d -2-> its 0-neighbour, one direction only
  auto r = check_validity(g);
  ASSERT_FALSE(r.ok());
  bool at_d = false;
  for (const auto& v : r.violations) {
    if (v.kind == ViolationKind::NotInvolution && v.dart == d && v.i == 2) at_d = true;
  }
  EXPECT_TRUE(at_d);
  (void)e;
}

TEST(Validity, CycleConstraintReportsPath) {
  Map g = make_polygon(3, 2);
  Map h = make_polygon(3, 2);
  // Link only one dart of a face to a dart of another polygon by alpha_2: breaks C(0,2).
  const Dart base = g.add_darts(h.capacity());
  for (int i = 0; i <= 1; ++i)
    for (Dart d = 0; d < h.capacity(); ++d) g.set_alpha(i, base + d, base + h.alpha(i, d));
  g.link(2, 0, base);
  auto r = check_validity(g);
  ASSERT_FALSE(r.ok());
  for (const auto& v : r.violations) {
    EXPECT_EQ(v.kind, ViolationKind::Cycle);
    EXPECT_EQ(v.i, 0);
    EXPECT_EQ(v.j, 2);
    EXPECT_EQ(v.path.size(), 5u);
    EXPECT_EQ(v.path.front(), v.dart);
    EXPECT_NE(v.path.back(), v.dart);
  }
  EXPECT_EQ(r.violations.size(), 4u);  // 0, base and their 0-neighbours
}

TEST(Validity, DanglingLinkAndLimit) {
  Map g = make_cube(3);
  g.set_alpha(3, 5, 1000);
  auto r = check_validity(g);
  ASSERT_EQ(r.violations.size(), 1u);
  EXPECT_EQ(r.violations[0].kind, ViolationKind::DanglingLink);
  EXPECT_EQ(r.violations[0].dart, 5u);
  Map big = make_grid(10, 10, 2);
  // Loops on the even darts while their 1-partners still point back: many non-involutions.
  big.for_each_dart([&](Dart d) {
    if (d % 2 == 0) big.set_alpha(1, d, d);
  });
  auto rb = check_validity(big, 3);
  EXPECT_EQ(rb.violations.size(), 3u);
  EXPECT_GT(rb.truncated, 0u);
  EXPECT_FALSE(rb.ok());
}

TEST(Validity, OMapPermutation) {
  Map o = orient(make_cube(2));
  EXPECT_TRUE(is_valid(o));
  o.set_alpha(1, 0, o.alpha(1, 1));  // two darts share a beta_1 image
  auto r = check_validity(o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.violations[0].kind, ViolationKind::NotPermutation);
}

TEST(Validity, HighDimensions) {
  for (int n = 0; n <= 7; ++n) {
    Map g(n);
    g.add_darts(4);
    EXPECT_TRUE(is_valid(g)) << n;
    if (n >= 2) {
      g.link(0, 0, 1);
      g.link(n, 0, 2);  // 0n0n from 0: 0->1->1->0->2 != 0
      EXPECT_FALSE(is_valid(g)) << n;
    }
  }
}
