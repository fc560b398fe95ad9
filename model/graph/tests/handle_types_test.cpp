// Darts, D-graph nodes and arcs are distinct handle types (model/core/handle.hpp): none converts
// implicitly into another or from an integer. Checked at compile time; the runtime tests check the
// explicit conversions and the to_dgraph correspondence node v <-> dart v.
#include <gtest/gtest.h>

#include <type_traits>

#include "model/core/builders.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/match.hpp"

using namespace gmr;
using namespace gmr::graph;

static_assert(!std::is_convertible_v<Dart, Node>);
static_assert(!std::is_convertible_v<Node, Dart>);
static_assert(!std::is_convertible_v<Dart, ArcId>);
static_assert(!std::is_convertible_v<ArcId, Dart>);
static_assert(!std::is_convertible_v<Node, ArcId>);
static_assert(!std::is_convertible_v<ArcId, Node>);
static_assert(!std::is_constructible_v<Node, ArcId>);
static_assert(!std::is_constructible_v<ArcId, Node>);
static_assert(!std::is_convertible_v<int, Node>);
static_assert(!std::is_convertible_v<size_t, ArcId>);
static_assert(std::is_constructible_v<Node, uint32_t>);  // explicitly only
static_assert(!std::is_same_v<Node, ArcId>);

// Zero cost: a handle is a trivially copyable 4-byte value.
static_assert(sizeof(Node) == sizeof(uint32_t) && sizeof(ArcId) == sizeof(uint32_t));
static_assert(std::is_trivially_copyable_v<Node> && std::is_trivially_copyable_v<ArcId>);

// Tables say what indexes them.
template <class T, class I>
concept Indexable = requires(const T& t, I i) {
  t[i];
};
static_assert(Indexable<HandleVector<Node, int>, Node>);
static_assert(!Indexable<HandleVector<Node, int>, ArcId>);
static_assert(!Indexable<HandleVector<Node, int>, Dart>);
static_assert(!Indexable<rewrite::NodeMap, ArcId>);

// The single "no node".
static_assert(std::is_same_v<decltype(rewrite::kNoNode), decltype(graph::kNoNode)>);
static_assert(rewrite::kNoNode == graph::kNoNode && graph::kNoNode == Node::none());

TEST(HandleTypes, NodesOfToDGraphAreTheDartsOfACompactMap) {
  const Map g = make_cube(2);
  const DGraph dg = to_dgraph(g);
  ASSERT_EQ(dg.num_nodes(), g.size());
  for (Node v : dg.nodes()) {
    EXPECT_EQ(dg.name(v), std::to_string(dart_of(v)));
    EXPECT_EQ(node_of(dart_of(v)), v);
  }
}

TEST(HandleTypes, RangesAndComparisons) {
  DGraph dg;
  const Node a = dg.add_node("a"), b = dg.add_node("b");
  const ArcId e = dg.add_arc(a, b, 0);
  EXPECT_LT(a, b);
  EXPECT_EQ(a.index(), 0u);
  EXPECT_EQ(e, ArcId(0));
  uint32_t k = 0;
  for (Node v : dg.nodes()) EXPECT_EQ(v.index(), k++);
  EXPECT_EQ(k, 2u);
  EXPECT_EQ(std::hash<Node>()(b), std::hash<uint32_t>()(1));
}
