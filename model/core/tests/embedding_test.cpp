// Embeddings: one value per orbit, with a consistency check.
#include "model/core/embedding.hpp"

#include <gtest/gtest.h>

#include <array>

#include "model/core/builders.hpp"

using namespace gmr;

TEST(Embedding, PositionsOnVertices) {
  Map g = make_cube();
  Embedding<std::array<double, 3>> pos("position", OrbitType{1, 2});
  EXPECT_FALSE(pos.check(g).empty());  // nothing set yet: 8 vertices without value
  EXPECT_EQ(pos.check(g).size(), 8u);
  double k = 0;
  for (Dart rep : orbit_representatives(g, OrbitType{1, 2})) pos.set(g, rep, {k, k, k}), k += 1;
  EXPECT_TRUE(pos.check(g).empty());
  EXPECT_EQ(pos.get(g.alpha(1, 0)), pos.get(0));
  EXPECT_EQ(pos.get(g.alpha(2, 0)), pos.get(0));
  EXPECT_NE(pos.get(g.alpha(0, 0)), pos.get(0));
  // Break consistency on one dart.
  pos.set_dart(g, g.alpha(1, 0), {9, 9, 9});
  auto issues = pos.check(g);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_NE(issues[0].problem.find("two different values"), std::string::npos);
}

TEST(Embedding, ColourOnFacesAnyType) {
  Map g = make_cube();
  Embedding<std::string> colour("colour", OrbitType{0, 1});
  for (Dart rep : orbit_representatives(g, OrbitType{0, 1})) colour.set(g, rep, "red");
  EXPECT_TRUE(colour.check(g).empty());
  EXPECT_EQ(colour.get(5), "red");
  EXPECT_THROW(colour.get(1000), Error);
  Embedding<int> bad("x", OrbitType{3});
  EXPECT_THROW(bad.check(g), Error);
}
