// Pattern functor, graph schemes with (w,d) labels, their instantiation and rule schemes (thesis
// §4.2–4.4, Defs. 42–48).
#include "model/words/word_scheme.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/rewrite/match.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/source_tree.hpp"
#include "model/words/pattern_graph.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::scheme;
using namespace gmr::words;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

PathWord w(const char* s) { return parse_word(s); }

std::vector<Diagnostic> diags;
bool I(const Rule& r, int i) { return check_incident_arcs(r, i, diags); }
bool O(const Rule& r, int i) { return check_non_orientation(r, i, diags); }

// Every node of g is the source and the target of exactly one i-arc.
bool incident(const DGraph& g, int i) {
  for (Node v : g.nodes())
    if (g.successors(v, i).size() != 1 || g.predecessors(v, i).size() != 1) return false;
  return true;
}

// ---- F8 (Figs. 4.16–4.22) -------------------------------------------------------------------
// RECON of the {1,2,3}-graph (figure missing; its components are given in the text and Ex. 49 says
// a..d carry an oriented 1111-cycle): nodes a..h,
//   a -1-> b -1-> c -1-> d -1-> a (oriented), 2-loops on a..d;
//   e, f: 1-loops, e –2– f;
//   g, h: g –1– h, 2-loops;
//   3-arcs a–e, b–f, c–g, d–h (dropped by the pattern functor: no word of W uses 3).
// It is a {1,2,3}-combinatorial graph (I_G on 1, 2, 3).
DGraph f8_graph() {
  DGraph g;
  for (const char* n : {"a", "b", "c", "d", "e", "f", "g", "h"}) g.add_node(n);
  auto id = [&](const char* n) { return *g.find(n); };
  for (auto [s, t] : {std::pair{"a", "b"}, {"b", "c"}, {"c", "d"}, {"d", "a"}})
    g.add_arc(id(s), id(t), 1);
  for (const char* n : {"a", "b", "c", "d", "g", "h"}) g.add_arc(id(n), id(n), 2);
  for (const char* n : {"e", "f"}) g.add_arc(id(n), id(n), 1);
  g.add_link(id("e"), id("f"), 2);
  g.add_link(id("g"), id("h"), 1);
  for (auto [s, t] : {std::pair{"a", "e"}, {"b", "f"}, {"c", "g"}, {"d", "h"}})
    g.add_link(id(s), id(t), 3);
  return g;
}

const std::vector<PathWord> kF8Words = {w("eps"), w("21"), conj(w("21"))};

// Rule scheme of Fig. 4.19a: hook y, added x. L: y with one 1-loop whose word is not given
// (the reading under which Ex. 49 holds). R: y –(eps,1)– x (both directions), x with a (21,2)-loop.
// Reading chosen: the L-loop is (eps,1). It is the only word of W = {eps, 21, conj(21)} that is
// self-conjugate, so the only one for which the claimed O_S(1) holds (Def. 51 (2): a loop is its
// own reverse, so its word must equal its conjugate; 21 ≠ ~1~2). The scheme then attaches a new
// dart x to every dart of P_v that is 1-free (carries a 1-loop). With the other reading (21),
// ι(S,P) breaks O(1) on the oriented component a..d (tested below), contradicting the claim, and
// Ex. 49's match (y,a) ↦ a ... (y,d) ↦ d on the oriented 1111-cycle cannot be reconciled with
// either reading together with O_S(1).
WordRuleScheme fig419a(const char* loop_word = "eps") {
  WordRuleScheme s;
  s.name = "fig4.19a";
  s.n = 3;
  s.kind = MapKind::GMap;
  s.hook = "y";
  s.left.add_node("y");
  s.left.add_arc("y", "y", loop_word, 1);
  s.right.add_node("y");
  s.right.add_node("x");
  s.right.add_link("y", "x", "eps", 1);
  s.right.add_arc("x", "x", "21", 2);
  return s;
}

// ---- F10: S_O, 2-O-map quad subdivision (Fig. 4.27, the version with 8 arcs in R) --------
WordRuleScheme quad_omap() {
  WordRuleScheme s;
  s.name = "S_O";
  s.n = 2;
  s.kind = MapKind::OMap;
  s.hook = "a";
  s.left.add_node("a");
  s.left.add_arc("a", "a", "1", 1);
  s.left.add_arc("a", "a", "2", 2);
  for (const char* n : {"a", "b", "c", "d"}) s.right.add_node(n);
  s.right.add_arc("b", "a", "1", 1);
  s.right.add_arc("a", "c", "eps", 1);
  s.right.add_arc("c", "d", "~1", 1);
  s.right.add_arc("d", "b", "eps", 1);
  s.right.add_arc("a", "b", "2", 2);
  s.right.add_arc("b", "a", "2", 2);
  s.right.add_arc("c", "d", "eps", 2);
  s.right.add_arc("d", "c", "eps", 2);
  return s;
}
const std::vector<PathWord> kOmapWords = {w("eps"), w("1"), w("~1"), w("2")};

// ---- F9: S_G, 2-G-map quad subdivision (Fig. 4.26 = Fig. 6.15) -------------------------------
WordRuleScheme quad_gmap() {
  WordRuleScheme s;
  s.name = "S_G";
  s.n = 2;
  s.kind = MapKind::GMap;
  s.hook = "a";
  s.left.add_node("a");
  for (int d = 0; d <= 2; ++d) s.left.add_arc("a", "a", std::to_string(d).c_str(), d);
  for (const char* n : {"a", "b", "c", "d"}) s.right.add_node(n);
  s.right.add_arc("a", "a", "1", 1);
  s.right.add_arc("a", "a", "2", 2);
  s.right.add_arc("b", "b", "2", 2);
  s.right.add_arc("c", "c", "0", 2);
  s.right.add_arc("d", "d", "0", 2);
  s.right.add_arc("d", "d", "1", 1);
  s.right.add_link("a", "b", "eps", 0);
  s.right.add_link("b", "c", "eps", 1);
  s.right.add_link("c", "d", "eps", 0);
  return s;
}
const std::vector<PathWord> kGmapWords = {w("eps"), w("0"), w("1"), w("2")};

size_t max_face_size(const Map& g, const OrbitType& face) {
  size_t mx = 0, mn = SIZE_MAX;
  for (Dart d : orbit_representatives(g, face)) {
    const size_t k = orbit(g, face, d).size();
    mx = std::max(mx, k);
    mn = std::min(mn, k);
  }
  return mx == mn ? mx : 0;  // 0: faces of different sizes
}

}  // namespace

TEST(PatternFunctor, Def48OnCubeGmapAndOmap) {
  const Map cube = make_cube(2);
  const PatternGraph P = pattern_graph(cube, kGmapWords);
  ASSERT_EQ(P.size(), 48u);
  EXPECT_EQ(P.graph.num_arcs(), 48u * 4);
  for (Node v : P.graph.nodes()) {
    EXPECT_EQ(P.targets(v, w("eps")), std::vector<Node>{v});  // ε-loop
    for (int i = 0; i <= 2; ++i)
      EXPECT_EQ(P.targets(v, PathWord{{i, false}}),
                std::vector<Node>{node_of(cube.alpha(i, dart_of(v)))});
  }
  EXPECT_EQ(components(P).size(), 1u);
  // Longer words follow the path: 01 then back with conj.
  const PatternGraph P2 = pattern_graph(cube, {w("01"), conj(w("01"))});
  for (Node v : P2.graph.nodes()) {
    const Node t = P2.targets(v, w("01"))[0];
    EXPECT_EQ(dart_of(t), cube.alpha(1, cube.alpha(0, dart_of(v))));
    EXPECT_EQ(P2.targets(t, w("~1~0")), std::vector<Node>{v});
  }
  // O-map: ~1 follows the 1-arc backwards (beta_1^{-1}).
  const Map om = orient(make_cube(2));
  ASSERT_EQ(om.size(), 24u);
  const PatternGraph Po = pattern_graph(om, kOmapWords);
  for (Node v : Po.graph.nodes()) {
    const Node s = Po.targets(v, w("1"))[0];
    EXPECT_EQ(Po.targets(s, w("~1")), std::vector<Node>{v});
    EXPECT_NE(s, Po.targets(v, w("~1"))[0]);  // faces are quads: beta_1 is not an involution
  }
  // A graph without incident arcs on a letter of W is rejected with the node named.
  DGraph bad;
  bad.add_node("p");
  EXPECT_THROW(pattern_graph(bad, {w("1")}), Error);
  EXPECT_NO_THROW(pattern_graph(bad, {w("eps")}));
}

TEST(F8, PatternComponentsAndEpsLoops) {
  const DGraph G = f8_graph();
  for (int i = 1; i <= 3; ++i) ASSERT_TRUE(incident(G, i));
  const PatternGraph P = pattern_graph(G, kF8Words);
  ASSERT_EQ(P.size(), 8u);
  EXPECT_EQ(P.graph.num_arcs(), 8u * 3);  // one arc per word and node, no 3-arc left
  for (Node v : P.graph.nodes()) {
    EXPECT_EQ(P.targets(v, w("eps")), std::vector<Node>{v});
    // conj(21)-arcs are the reverses of the 21-arcs.
    const Node t = P.targets(v, w("21"))[0];
    EXPECT_EQ(P.targets(t, w("~1~2")), std::vector<Node>{v});
  }
  // 21 on a..d: a -> b -> c -> d -> a.
  EXPECT_EQ(P.targets(*G.find("a"), w("21")), std::vector<Node>{*G.find("b")});
  EXPECT_EQ(P.targets(*G.find("e"), w("21")), std::vector<Node>{*G.find("f")});
  // Components P_{a..d}, P_{e,f}, P_{g,h} (node ids a=0 ... h=7).
  auto ids = [](std::initializer_list<uint32_t> l) {
    std::vector<Node> v;
    for (uint32_t x : l) v.push_back(Node(x));
    return v;
  };
  EXPECT_EQ(components(P),
            (std::vector<std::vector<Node>>{ids({0, 1, 2, 3}), ids({4, 5}), ids({6, 7})}));
  const PatternGraph Pf = component(P, *G.find("f"));
  ASSERT_EQ(Pf.size(), 2u);
  EXPECT_EQ(Pf.graph.name(Node(0)), "f");
  EXPECT_EQ(Pf.graph.name(Node(1)), "e");
  EXPECT_EQ(Pf.origin, ids({5, 4}));
  EXPECT_EQ(Pf.graph.num_arcs(), 6u);
  // With a word using 3, the components merge (the 3-arcs are no longer dropped).
  EXPECT_EQ(components(pattern_graph(G, {w("eps"), w("3"), w("21"), conj(w("21"))})).size(), 1u);
}

TEST(F8, Fig419aInstantiatedOnEachComponent) {
  const DGraph G = f8_graph();
  const PatternGraph P = pattern_graph(G, kF8Words);
  const WordRuleScheme S = fig419a();
  // Scheme level: the L-loop is deleted, nothing else of L.
  EXPECT_EQ(S.preserved_arcs(), (std::vector<std::optional<uint32_t>>{std::nullopt}));
  // The core rule: I(1), I(2), O(1) (the scheme-level claims, Thm. 4/5 with P = 1_W).
  const Rule core = S.core();
  EXPECT_TRUE(I(core, 1));
  EXPECT_TRUE(I(core, 2));
  EXPECT_TRUE(O(core, 1));
  for (const char* hook : {"a", "e", "g"}) {
    const PatternGraph Pv = component(P, *G.find(hook));
    const size_t k = Pv.size();
    const Rule r = instantiate_word_rule(S, Pv);
    EXPECT_EQ(r.left().num_nodes(), k) << hook;
    EXPECT_EQ(r.right().num_nodes(), 2 * k) << hook;
    EXPECT_EQ(r.left().num_arcs(), k) << hook;       // one 1-loop per (u,y)
    EXPECT_EQ(r.right().num_arcs(), 3 * k) << hook;  // (u,y) <-> (u,x), and the 2-arc of (u,x)
    EXPECT_EQ(r.added_nodes().size(), k);
    EXPECT_TRUE(r.right().find(Pv.graph.name(Node(0)) + ":x").has_value());
    // The thesis' claims, checked by the concrete checker on ι(S,P_v).
    EXPECT_TRUE(I(r, 1)) << hook;
    EXPECT_TRUE(I(r, 2)) << hook;
    EXPECT_TRUE(O(r, 1)) << hook;
    // O(2) is not claimed: the (21,2)-loop of x gives u:x -2-> t_21(u):x, non-oriented only where
    // t_21 is an involution (components e,f and g,h, not the 4-cycle a..d).
    EXPECT_EQ(O(r, 2), k == 2) << hook;
  }
  // The other reading (21 on the L-loop) breaks O(1) on a..d: rejected.
  const Rule r21 = instantiate_word_rule(fig419a("21"), component(P, Node(0)));
  EXPECT_TRUE(I(r21, 1));
  EXPECT_FALSE(O(r21, 1));
  EXPECT_NE(conj(w("21")), w("21"));
}

TEST(F8, Fig419aMatchAndDerivation) {
  const DGraph G = f8_graph();
  const PatternGraph P = pattern_graph(G, kF8Words);
  const WordRuleScheme S = fig419a();
  // On a..d the (eps,1)-loops of ι(L,P) need 1-loops in G: no match (Ex. 49).
  const PatternGraph Pa = component(P, Node(0));
  EXPECT_FALSE(propagate_match(S, Pa, instantiate_word_rule(S, Pa), G).has_value());
  // On e,f (1-free darts) the match is (u,y) ↦ u, and the derivation keeps I(1), I(2).
  const PatternGraph Pe = component(P, *G.find("e"));
  const Rule r = instantiate_word_rule(S, Pe);
  const auto m = propagate_match(S, Pe, r, G);
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(*m, Pe.origin);
  const auto match = match_from_nodes(r.left(), G, *m);
  ASSERT_TRUE(match.has_value());
  const Derivation der = derive(r, G, *match);
  EXPECT_EQ(der.H.num_nodes(), 10u);
  EXPECT_TRUE(incident(der.H, 1));
  EXPECT_TRUE(incident(der.H, 2));
  // x's 2-arcs: (e,x) <-> (f,x).
  const Node ex = der.comatch[*r.right().find("e:x")], fx = der.comatch[*r.right().find("f:x")];
  EXPECT_EQ(der.H.successors(ex, 2), std::vector<Node>{fx});
}

TEST(WordScheme, InstantiationOperationalForm) {
  // ι(Π,1_W) = π_D(Π): on a one-node pattern with ε only, a (eps,d)-arc n -> n' gives d-arc n ->
  // n'.
  DGraph one;
  one.add_node("u");
  const PatternGraph P1 = pattern_graph(one, {w("eps")});
  WordGraphScheme Pi;
  Pi.add_node("n");
  Pi.add_node("m");
  Pi.add_link("n", "m", "eps", 0);
  const DGraph I1 = instantiate_word_graph(Pi, P1);
  EXPECT_EQ(I1.num_nodes(), 2u);
  EXPECT_EQ(I1.name(Node(1)), "u:m");
  EXPECT_EQ(I1.successors(Node(0), 0), std::vector<Node>{Node(1)});
  // Words not in W are rejected; duplicate and empty names too.
  Pi.add_arc("n", "n", "2", 2);
  EXPECT_THROW(instantiate_word_graph(Pi, P1), Error);
  EXPECT_THROW(Pi.add_node("n"), Error);
  EXPECT_THROW(Pi.add_arc("n", "zz", "eps", 0), Error);
  // add_link on a loop with a non-self-conjugate word adds both loops.
  WordGraphScheme L;
  L.add_node("x");
  L.add_link("x", "x", "21", 2);
  ASSERT_EQ(L.arcs.size(), 2u);
  EXPECT_EQ(L.arcs[1].word, w("~1~2"));
  // Words are literal at the scheme level (no ~d := d for d ∈ N): conj(0) = ~0, a second loop.
  // Non-oriented loops of N dimensions are written with add_arc, as in quad_gmap().
  L.add_link("x", "x", "0", 0);
  ASSERT_EQ(L.arcs.size(), 4u);
  EXPECT_EQ(L.arcs[3].word, w("~0"));
}

TEST(F10, OmapQuadSubdivisionOnCube) {
  const Map om = orient(make_cube(2));
  ASSERT_EQ(om.size(), 24u);
  ASSERT_TRUE(is_valid(om));
  const WordRuleScheme S = quad_omap();
  // All arcs of L deleted at scheme level (R has no loop on a).
  EXPECT_EQ(S.preserved_arcs(), (std::vector<std::optional<uint32_t>>{std::nullopt, std::nullopt}));
  const WordSchemeInstance app = instantiate_at(om, S, kOmapWords, 0);
  EXPECT_EQ(app.pattern.size(), 24u);
  EXPECT_EQ(app.rule.left().num_nodes(), 24u);
  EXPECT_EQ(app.rule.right().num_nodes(), 96u);
  EXPECT_EQ(app.rule.right().num_arcs(), 8u * 24);
  const Map H = apply(app.rule, om, app.match, Construction::Categorical).H;
  EXPECT_EQ(H.kind(), MapKind::OMap);
  EXPECT_EQ(H.size(), 96u);
  EXPECT_TRUE(is_valid(H));
  EXPECT_EQ(count_all_cells(H), (std::vector<size_t>{26, 48, 24}));
  EXPECT_EQ(euler_characteristic(H), 2);
  EXPECT_EQ(max_face_size(H, OrbitType::parse("<1>")), 4u);  // every face has 4 darts
  // The concrete checker on ι(S_O, P_v).
  EXPECT_TRUE(I(app.rule, 1));
  EXPECT_TRUE(I(app.rule, 2));
  EXPECT_TRUE(O(app.rule, 2));
  EXPECT_TRUE(check_combinatorial(app.rule, diags));
  EXPECT_TRUE(check_rule(app.rule).ok()) << to_text(check_rule(app.rule));
  // A broken variant (c -> d with word 1 instead of ~1) no longer gives quads.
  WordRuleScheme bad = S;
  bad.right.arcs[2].word = w("1");
  const WordSchemeInstance app2 = instantiate_at(om, bad, kOmapWords, 0);
  const Map H2 = apply(app2.rule, om, app2.match, Construction::Categorical).H;
  EXPECT_NE(max_face_size(H2, OrbitType::parse("<1>")), 4u);
}

TEST(F9, GmapQuadSubdivisionOnCubeAgreesWithJerboaEngine) {
  const Map cube = make_cube(2);
  const WordRuleScheme S = quad_gmap();
  // Scheme level: the (1,1) and (2,2) loops of a are preserved, the (0,0) loop deleted.
  const auto pres = S.preserved_arcs();
  ASSERT_EQ(pres.size(), 3u);
  EXPECT_FALSE(pres[0].has_value());
  EXPECT_EQ(pres[1], std::optional<uint32_t>{0});
  EXPECT_EQ(pres[2], std::optional<uint32_t>{1});
  const WordSchemeInstance app = instantiate_at(cube, S, kGmapWords, 0);
  EXPECT_EQ(app.rule.left().num_nodes(), 48u);
  EXPECT_EQ(app.rule.left().num_arcs(), 3u * 48);  // L = N nodes / 3N arcs (a loop counts once)
  EXPECT_EQ(app.rule.right().num_nodes(), 4u * 48);
  const Map H = apply(app.rule, cube, app.match, Construction::Categorical).H;
  EXPECT_EQ(H.size(), 192u);
  EXPECT_TRUE(is_valid(H));
  EXPECT_EQ(count_all_cells(H), (std::vector<size_t>{26, 48, 24}));
  EXPECT_EQ(euler_characteristic(H), 2);
  EXPECT_EQ(max_face_size(H, OrbitType::parse("<0,1>")), 8u);
  for (int i = 0; i <= 2; ++i) {
    EXPECT_TRUE(I(app.rule, i)) << i;
    EXPECT_TRUE(O(app.rule, i)) << i;
  }
  EXPECT_TRUE(check_cycle(app.rule, 0, 2, diags));
  // Jerboa-scheme engine on tools/data/rules/quad_subdivision.json.
  const RuleScheme js =
      read_scheme_file(gmr::testing::source_path("tools/data/rules/quad_subdivision.json"));
  const auto [J, japp] = scheme::apply(SchemeEngine(js), std::as_const(cube), {0});
  ASSERT_TRUE(japp.applied) << japp.why;
  EXPECT_EQ(J.size(), 192u);
  EXPECT_TRUE(is_isomorphic(H, J));
  // And differs from a subdivision that is not the same operation (sanity of is_isomorphic).
  const Map tet = make_tetrahedron(2);
  const WordSchemeInstance at = instantiate_at(tet, S, kGmapWords, 0);
  const Map tri = apply(at.rule, tet, at.match, Construction::Categorical).H;
  EXPECT_FALSE(is_isomorphic(H, tri));
}
