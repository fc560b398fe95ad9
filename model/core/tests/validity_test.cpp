// Validity reports every violation with its location (dart, dimensions, path).
#include "model/core/validity.hpp"

#include <gtest/gtest.h>

#include <random>

#include "model/core/builders.hpp"

using namespace gmr;

TEST(Validity, BrokenInvolutionReported) {
  Map g = make_cube(2);
  const Dart d = 0, e = g.alpha(2, 0);
  g.set_alpha(2, d, g.alpha(0, d));  // d -2-> its 0-neighbour, one direction only
  auto r = check_validity(g);
  ASSERT_FALSE(r.ok());
  bool at_d = false;
  for (const auto& v : r.violations) {
    if (v.constraint == Constraint::NonOrientation && v.at == d && v.i == 2) at_d = true;
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
    EXPECT_EQ(v.constraint, Constraint::Cycle);
    EXPECT_EQ(v.i, 0);
    EXPECT_EQ(v.j, 2);
    EXPECT_EQ(v.path.size(), 5u);
    EXPECT_EQ(v.path.front(), v.at);
    EXPECT_NE(v.path.back(), v.at);
  }
  EXPECT_EQ(r.violations.size(), 4u);  // 0, base and their 0-neighbours
}

TEST(Validity, DanglingLinkAndLimit) {
  Map g = make_cube(3);
  g.set_alpha(3, 5, 1000);
  auto r = check_validity(g);
  ASSERT_EQ(r.violations.size(), 1u);
  EXPECT_EQ(r.violations[0].constraint, Constraint::IncidentArcs);
  EXPECT_EQ(r.violations[0].at, 5u);
  EXPECT_EQ(to_text(r.violations[0]),
            "incident-arcs at dart 5: its 3-link targets 1000, which is not a dart");
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
  EXPECT_EQ(r.violations[0].constraint, Constraint::IncidentArcs);
  EXPECT_EQ(r.violations[0].i, 1);
  EXPECT_NE(r.violations[0].message.find("beta_1 not a permutation"), std::string::npos);
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

namespace {

// Thesis Def. 1 read literally: every link is a dart, every alpha_i an involution, and
// (alpha_i alpha_j)^2 the identity for i + 2 <= j.
bool valid_by_definition(const Map& g) {
  const int n = g.dimension();
  const Dart cap = g.capacity();
  for (Dart d = 0; d < cap; ++d)
    for (int i = 0; i <= n; ++i) {
      const Dart e = g.alpha(i, d);
      if (e >= cap || g.alpha(i, e) != d) return false;
    }
  for (Dart d = 0; d < cap; ++d)
    for (int i = 0; i <= n; ++i)
      for (int j = i + 2; j <= n; ++j)
        if (g.alpha(i, g.alpha(j, g.alpha(i, g.alpha(j, d)))) != d) return false;
  return true;
}

}  // namespace

// The verdict on G-maps without deleted darts (one pass over the darts when the map is valid, the
// per-condition passes otherwise) is the definition's, on maps broken in every way a link can be:
// a link out of range, a link set in one direction only, two i-links exchanged (alpha_i stays an
// involution; the cycle conditions may break or not).
TEST(Validity, VerdictIsTheDefinitionsOnBrokenGMaps) {
  std::mt19937 rng(20261203);
  size_t valid = 0, invalid = 0;
  for (int round = 0; round < 600; ++round) {
    Map g = round % 3 == 0 ? make_cube(3) : round % 3 == 1 ? make_grid(3, 2, 2) : make_cube(2);
    const Dart cap = g.capacity();
    const int n = g.dimension();
    auto dart = [&] { return static_cast<Dart>(rng() % cap); };
    const int i = static_cast<int>(rng() % static_cast<unsigned>(n + 1));
    const Dart d = dart(), e = dart();
    switch (round % 4) {
      case 0:
        g.set_alpha(i, d, cap + static_cast<Dart>(rng() % 3));
        break;
      case 1:
        g.set_alpha(i, d, e);
        break;
      default: {  // d -i- e and d1 -i- e1 for d -i- d1 and e -i- e1
        const Dart d1 = g.alpha(i, d), e1 = g.alpha(i, e);
        if (d == e || d1 == e) break;  // nothing to exchange
        g.set_alpha(i, d1, e1), g.set_alpha(i, e1, d1);
        g.set_alpha(i, d, e), g.set_alpha(i, e, d);
        if (d1 == d && e1 != e) g.set_alpha(i, e1, e1);  // d was free: e's partner becomes free
        if (e1 == e && d1 != d) g.set_alpha(i, d1, d1);
      }
    }
    const bool expected = valid_by_definition(g);
    EXPECT_EQ(check_validity(g).ok(), expected) << "round " << round;
    EXPECT_EQ(is_valid(g), expected) << "round " << round;
    (expected ? valid : invalid) += 1;
  }
  EXPECT_GT(valid, 50u);
  EXPECT_GT(invalid, 300u);
}
