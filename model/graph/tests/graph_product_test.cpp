// Products of Σ-graphs, arc deletion Δ_i and arc relabeling ℜ (thesis §4.2.1–4.2.2, Def. 41,
// Ex. 42 / Fig. 4.12).
#include "model/graph/graph_product.hpp"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::graph;

namespace {

using ArcSet = std::multiset<std::tuple<Node, Node, int>>;
ArcSet arcs(const DGraph& g) {
  ArcSet s;
  for (ArcId a : g.arc_slots())
    if (g.arc_alive(a)) s.insert({g.arc(a).src, g.arc(a).tgt, g.arc(a).label});
  return s;
}

// F15 alphabet Σ = {i, i', j, j', k, d} as six ints.
constexpr int i_ = 10, ip = 11, j_ = 20, jp = 21, k_ = 30, d_ = 40;
const Alphabet kSigma = {i_, ip, j_, jp, k_, d_};

// A graph with arcs of every letter, loops and parallel arcs.
DGraph sample() {
  DGraph g;
  const Node a = g.add_node("a"), b = g.add_node("b"), c = g.add_node("c");
  g.add_node("isolated");
  g.add_arc(a, b, i_);
  g.add_arc(a, b, i_);  // parallel
  g.add_arc(b, a, ip);
  g.add_arc(b, c, j_);
  g.add_arc(c, c, jp);  // loop
  g.add_arc(c, a, k_);
  g.add_arc(a, a, k_);
  g.add_arc(b, b, d_);
  g.add_arc(c, b, d_);
  return g;
}

}  // namespace

TEST(Product, NodesArcsAndNames) {
  const DGraph P = sample();
  DGraph Pi;
  const Node x = Pi.add_node("x"), y = Pi.add_node("y");
  Pi.add_arc(x, y, i_);
  Pi.add_arc(y, y, i_);
  Pi.add_arc(x, x, d_);
  const DGraph G = product(P, Pi, kSigma);
  EXPECT_EQ(G.num_nodes(), 8u);  // all pairs, isolated ones included
  EXPECT_EQ(G.name(product_node(Pi, Node(2), Node(1))), "c,y");
  // |E| = Σ_l |E_P(l)|·|E_Π(l)| = 2·2 (i) + 2·1 (d).
  EXPECT_EQ(G.num_arcs(), 6u);
  ArcSet expected;
  // each of the two parallel i-arcs a->b of P with x->y and with y->y
  expected.insert({product_node(Pi, Node(0), x), product_node(Pi, Node(1), y), i_});
  expected.insert({product_node(Pi, Node(0), x), product_node(Pi, Node(1), y), i_});
  expected.insert({product_node(Pi, Node(0), y), product_node(Pi, Node(1), y), i_});
  expected.insert({product_node(Pi, Node(0), y), product_node(Pi, Node(1), y), i_});
  expected.insert({product_node(Pi, Node(1), x), product_node(Pi, Node(1), x), d_});
  expected.insert({product_node(Pi, Node(2), x), product_node(Pi, Node(1), x), d_});
  EXPECT_EQ(arcs(G), expected);
  // With 1_Σ the product is P itself (terminal object).
  EXPECT_EQ(arcs(product(P, terminal(kSigma), kSigma)), arcs(P));
  // Labels outside Σ are rejected.
  DGraph bad;
  bad.add_arc(bad.add_node("z"), Node(0), 99);
  EXPECT_THROW(product(bad, Pi, kSigma), Error);
}

TEST(F15, DeltaDeletesExactlyTheIArcs) {
  const DGraph P = sample();
  for (int del : kSigma) {
    const DGraph D = delta(kSigma, del);
    EXPECT_EQ(D.num_nodes(), 1u);
    EXPECT_EQ(D.num_arcs(), kSigma.size() - 1);
    const DGraph G = delete_arcs(P, kSigma, del);
    ASSERT_EQ(G.num_nodes(), P.num_nodes());
    ArcSet expected;
    for (auto [s, t, l] : arcs(P))
      if (l != del) expected.insert({s, t, l});
    EXPECT_EQ(arcs(G), expected) << "Δ_" << del;
    EXPECT_LT(G.num_arcs(), P.num_arcs());  // every letter occurs in the sample
  }
  EXPECT_THROW(delta(kSigma, 7), Error);
}

TEST(F15, RelabelingIJIpJpKK) {
  const DGraph P = sample();
  const Relabeling rel = {{i_, j_}, {ip, jp}, {k_, k_}};
  const DGraph lit = relabel_literal(P, kSigma, rel);
  const DGraph dir = relabel(P, kSigma, rel);
  // i -> j, i' -> j', k kept; d, j and j' arcs deleted (they have no pair in ℜ).
  ArcSet expected;
  for (auto [s, t, l] : arcs(P)) {
    if (l == i_) expected.insert({s, t, j_});
    if (l == ip) expected.insert({s, t, jp});
    if (l == k_) expected.insert({s, t, k_});
  }
  EXPECT_EQ(expected.size(), 5u);
  EXPECT_EQ(arcs(dir), expected);
  EXPECT_EQ(arcs(lit), expected);  // Def. 41 literally = direct
  EXPECT_EQ(lit.num_nodes(), P.num_nodes());
  // The intermediate objects of Def. 41.
  const DGraph E = embed_pairs(P, kSigma);
  EXPECT_EQ(E.num_arcs(), P.num_arcs() * kSigma.size());
  const DGraph Pr = relabeling_graph(kSigma, rel);
  EXPECT_EQ(Pr.num_arcs(), 3u);
  EXPECT_EQ(label_pair(kSigma, pair_label(kSigma, ip, jp)), (std::pair<int, int>{ip, jp}));
  // Swapping and identity: literal and direct agree on other relabelings too.
  for (const Relabeling& r :
       std::vector<Relabeling>{{{i_, ip}, {ip, i_}},
                               {},
                               {{d_, d_}, {j_, i_}},
                               {{i_, i_}, {ip, ip}, {j_, j_}, {jp, jp}, {k_, k_}, {d_, d_}}}) {
    EXPECT_EQ(arcs(relabel_literal(P, kSigma, r)), arcs(relabel(P, kSigma, r)));
  }
  EXPECT_EQ(arcs(relabel(P, kSigma, {{i_, i_}, {ip, ip}, {j_, j_}, {jp, jp}, {k_, k_}, {d_, d_}})),
            arcs(P));
  EXPECT_EQ(relabel(P, kSigma, {}).num_arcs(), 0u);
  // At most one image per letter.
  EXPECT_THROW(relabel(P, kSigma, {{i_, j_}, {i_, jp}}), Error);
  EXPECT_THROW(relabel_literal(P, kSigma, {{i_, j_}, {i_, jp}}), Error);
}

TEST(Product, Ex42Fig412) {
  // RECON (figure missing): ◦ = 0, • = 1. P: a with a ◦-loop, •-arc b -> c, ◦-arc a -> b.
  // Π: x with a ◦-loop, •-arc y -> x; y has no ◦-arc.
  constexpr int circ = 0, bullet = 1;
  DGraph P;
  const Node a = P.add_node("a"), b = P.add_node("b"), c = P.add_node("c");
  P.add_arc(a, a, circ);
  P.add_arc(b, c, bullet);
  P.add_arc(a, b, circ);
  DGraph Pi;
  const Node x = Pi.add_node("x"), y = Pi.add_node("y");
  Pi.add_arc(x, x, circ);
  Pi.add_arc(y, x, bullet);
  const DGraph G = product(Pi, P, {circ, bullet});
  EXPECT_EQ(G.num_nodes(), 6u);
  auto at = [&](Node u, Node v) { return product_node(P, u, v); };
  // ◦-loop on x × ◦-loop on a = ◦-loop on (x,a).
  EXPECT_EQ(G.successors(at(x, a), circ), (std::vector<Node>{at(x, a), at(x, b)}));
  EXPECT_EQ(G.name(at(x, a)), "x,a");
  // •-arc y -> x × •-arc b -> c = •-arc (y,b) -> (x,c).
  EXPECT_EQ(G.successors(at(y, b), bullet), std::vector<Node>{at(x, c)});
  // No ◦-arc leaves (y,·): y has no ◦-arc.
  for (Node v : {a, b, c}) EXPECT_TRUE(G.successors(at(y, v), circ).empty());
  EXPECT_EQ(G.num_arcs(), 3u);  // 1·2 (◦) + 1·1 (•)
}
