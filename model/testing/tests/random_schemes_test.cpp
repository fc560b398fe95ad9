// Random rule schemes (model/random_schemes.hpp): structurally valid, deterministic, and the
// copies family has the announced shape.
#include "model/testing/random_schemes.hpp"

#include <gtest/gtest.h>

#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::testing;

TEST(RandomSchemes, StructurallyValidAndDeterministic) {
  size_t with_added = 0, two_left = 0;
  for (uint64_t seed = 0; seed < 300; ++seed) {
    for (int n = 1; n <= 3; ++n) {
      Rng a(seed), b(seed);
      RandomSchemeOptions o;
      o.n = n;
      const RuleScheme s = random_scheme(a, o);
      EXPECT_NO_THROW(s.validate_structure()) << "seed " << seed;
      EXPECT_EQ(s, random_scheme(b, o));
      EXPECT_FALSE(s.orbit.has_hole());
      EXPECT_EQ(s.hooks, std::vector<std::string>{"n0"});
      two_left += s.left.size() == 2;
      for (uint32_t v = 0; v < s.right.size(); ++v) with_added += !s.left_of(v).has_value();
      RuleScheme m = s;
      const std::string what = mutate_scheme(a, m);
      EXPECT_NO_THROW(m.validate_structure()) << what;
      if (what != "none") {
        EXPECT_NE(m, s) << what;
      }
    }
  }
  EXPECT_GT(with_added, 100u);
  EXPECT_GT(two_left, 20u);
}

TEST(RandomSchemes, CopiesShape) {
  for (uint64_t seed = 0; seed < 100; ++seed) {
    Rng r(seed);
    const RuleScheme s = random_copies_scheme(r, 2, 3);
    EXPECT_NO_THROW(s.validate_structure());
    EXPECT_EQ(s.orbit, OrbitType({0, 1, 2}));
    ASSERT_EQ(s.left.size(), 1u);
    EXPECT_GE(s.right.size(), 1u);
    EXPECT_LE(s.right.size(), 3u);
    EXPECT_TRUE(s.right.arcs.empty());
    for (const auto& v : s.right.nodes)
      EXPECT_TRUE(v.label == OrbitType({0, 1, 2}) || v.label == OrbitType({2, 1, 0}));
  }
}
