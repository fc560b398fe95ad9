// Worked examples of the thesis (Ch. 3 examples and figures) that are concrete rules, loaded from
// checker/tests/data/*.json (gmr.rule), checked statically and — where the rule is applicable to
// small maps — against the semantics. The rule-scheme, rewriting-system and product fixtures are in
// model/words/tests/word_scheme_test.cpp (F8, F9, F10), model/words/tests/word_rewriting_test.cpp
// (F14) and model/graph/tests/graph_product_test.cpp (F15).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "checker/semantic.hpp"
#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

std::string data(const std::string& name) {
  return gmr::testing::source_path("checker/tests/data/" + name + ".json");
}

Rule load(const std::string& name) { return read_rule_file(data(name)); }

std::vector<Diagnostic> diags;

bool wI(const Rule& r, int i) { return check_weak_incident_arcs(r, i, diags); }
bool I(const Rule& r, int i) { return check_incident_arcs(r, i, diags); }
bool O(const Rule& r, int i) { return check_non_orientation(r, i, diags); }
bool C(const Rule& r, int i, int j) { return check_cycle(r, i, j, diags); }

// Applies r on g through the match "node name -> dart" given by name_to_dart, both ways.
Map apply_both(const Rule& r, const Map& g,
               const std::function<Dart(const std::string&)>& name_to_dart) {
  std::vector<Dart> m;
  for (Node v : r.left().nodes()) m.push_back(name_to_dart(r.left().name(v)));
  MapDerivation a = apply(r, g, m, Construction::Rewriting),
                b = apply(r, g, m, Construction::Categorical);
  EXPECT_TRUE(is_isomorphic(a.H, b.H));
  return a.H;
}

// The match of fixture rules whose node names end with their dart ("a3" -> dart 3).
Dart dart_by_index(const std::string& node) {
  return static_cast<Dart>(std::stoul(node.substr(1)));
}

Map isolated_face(size_t k) {  // 2k darts, numbering of the fixture generator
  Map g(2);
  g.add_darts(2 * k);
  for (Dart d = 0; d < 2 * k; d += 2) g.link(0, d, d + 1);
  for (Dart d = 1; d < 2 * k; d += 2) g.link(1, d, static_cast<Dart>((d + 1) % (2 * k)));
  return g;
}

// The fixture rule `name`, accepted by the checker, applied to the isolated face of k sides
// (matched by dart index): a valid map of `darts` darts and `cells` i-cells (i = 0..2).
void expect_on_isolated_face(const std::string& name, size_t k, size_t darts,
                             const std::vector<size_t>& cells) {
  const Rule r = load(name);
  const CheckReport rep = check_rule(r);
  EXPECT_TRUE(rep.ok()) << to_text(rep);
  const Map face = isolated_face(k);
  EXPECT_TRUE(is_valid(face));
  const Map h = apply_both(r, face, dart_by_index);
  EXPECT_TRUE(is_valid(h));
  EXPECT_EQ(h.size(), darts);
  EXPECT_EQ(count_all_cells(h), cells);
}

}  // namespace

TEST(Fixtures, F1_Ex34_WeakIncidentArcs) {
  const Rule r = load("F1_ex34_weak_incident");
  EXPECT_TRUE(wI(r, 2));
  EXPECT_FALSE(wI(r, 1));
  std::vector<Diagnostic> d;
  check_weak_incident_arcs(r, 1, d);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].code, "I-added-node");
  EXPECT_EQ(d[0].nodes, std::vector<std::string>{"d"});
}

TEST(Fixtures, F2_Ex35_ArcDeductionAndJointRepresentation) {
  const Rule r = load("F2_ex35_arc_deduction");
  size_t preserved = 0;
  for (ArcId a : r.left().arc_slots())
    if (r.left_arc_status(a) == ElemStatus::Preserved) ++preserved;
  EXPECT_EQ(preserved, 3u);  // c-1->b, 2-loop on c, b-3->c
  EXPECT_EQ(r.deleted_nodes().size(), 1u);
  EXPECT_EQ(r.added_nodes().size(), 1u);
  const JointRepresentation j = to_joint(r);
  EXPECT_EQ(j.graph.num_nodes(), 8u);  // a,b,c,d + κ(a),κ(b),κ(c),e
  size_t kappa = 0;
  for (ArcId a : j.graph.arc_slots()) kappa += j.graph.arc(a).label == kKappaLabel;
  EXPECT_EQ(kappa, 3u);
  const Rule back = from_joint(j);
  EXPECT_EQ(rule_to_json(back), rule_to_json(r));
}

TEST(Fixtures, F3_Ex37_NonOrientation) {
  const Rule r = load("F3_ex37_non_orientation");
  EXPECT_TRUE(O(r, 1));
  std::vector<Diagnostic> d;
  EXPECT_FALSE(check_non_orientation(r, 2, d));
  ASSERT_EQ(d.size(), 2u);  // the deleted a->c and the added c->a
  EXPECT_EQ(d[0].code, "O-no-reverse");
  EXPECT_EQ(d[0].side, Side::L);
  EXPECT_EQ(d[1].side, Side::R);
}

TEST(Fixtures, F4_Fig318_CycleCondition) {
  const Rule r = load("F4_fig318_flip");
  EXPECT_TRUE(C(r, 1, 2));
  // Ex. 39: in the rule as drawn, fecb is (1,3)-optimal. Assumption 5 then closes the 131-path
  // fecb by a preserved 3-arc b-f, which puts it on a 1313-cycle: after completion it is no longer
  // optimal, and C_r(1,3) fails through R's unpaired f-1-c, e-1-b and the rewired c, e.
  bool fecb = false;
  for (const auto& p : optimal_paths(r, graph::Side::L, 1, 3))
    if (r.left().name(p.source) == "f" && r.left().name(p.target) == "b" &&
        p.word == std::vector<int>{1, 3, 1})
      fecb = true;
  EXPECT_TRUE(fecb) << "the (1,3)-optimal path fecb of Ex. 39";
  std::vector<Diagnostic> d;
  EXPECT_FALSE(check_cycle(r, 1, 3, d));
  size_t completed = 0, incoherent = 0, rewired = 0;
  for (const auto& x : d) {
    completed += x.code == "C-completed";
    incoherent += x.code == "C-incoherent";
    rewired += x.code == "C-preserved-node";
  }
  EXPECT_EQ(completed, 2u);
  EXPECT_EQ(incoherent, 4u);
  EXPECT_EQ(rewired, 2u);
  EXPECT_FALSE(I(r, 3));  // as printed: the figure has no 3-loops on c and e
  // Optimal paths of Ex. 39: in L only f-e-h and h-e-f are (1,2)-optimal.
  const auto pl = optimal_paths(ij_complete(r, 1, 2), graph::Side::L, 1, 2);
  ASSERT_EQ(pl.size(), 2u);
  const Rule r3 = load("F4_fig318_flip_3loops");
  EXPECT_TRUE(I(r3, 3));
  EXPECT_TRUE(C(r3, 1, 2));
  EXPECT_FALSE(C(r3, 1, 3));
}

TEST(Fixtures, F5_Fig319a_SewAndUnsew) {
  const MapFamily fam = map_family(2, MapKind::GMap, 4);
  for (const char* name : {"F5_fig319a_sew", "F5_fig319a_unsew"}) {
    const Rule r = load(name);
    const CheckReport rep = check_rule(r);
    EXPECT_TRUE(rep.ok()) << to_text(rep);
    EXPECT_TRUE(rep.holds("C(0,2)"));
    const SemanticVerdict v = semantic_verdict(r, fam);
    EXPECT_TRUE(v.applicable());
    EXPECT_TRUE(v.preserves);
  }
  // L of the sewing rule has no (0,2)-optimal path (every node on a 0202-cycle of loops).
  EXPECT_TRUE(optimal_paths(load("F5_fig319a_sew"), graph::Side::L, 0, 2).empty());
}

TEST(Fixtures, F6_Fig319b_Partial) {
  const Rule r = load("F6_fig319b_partial");
  const CheckReport rep = check_rule(r);
  EXPECT_TRUE(rep.ok()) << to_text(rep);
  EXPECT_EQ(optimal_paths(r, graph::Side::L, 0, 2).size(), 2u);  // a-b-c and c-b-a
  const SemanticVerdict v = semantic_verdict(r, map_family(2, MapKind::GMap, 4));
  EXPECT_TRUE(v.applicable());
  EXPECT_TRUE(v.preserves);
}

TEST(Fixtures, F7_Fig424_CoreRule) {
  const Rule r = load("F7_fig424_core");
  EXPECT_TRUE(C(r, 1, 2));
  for (int i : {0, 1, 2, 3}) EXPECT_TRUE(I(r, i));
}

TEST(Fixtures, F9_F13_QuadSubdivisionOnIsolatedQuad) {
  expect_on_isolated_face("F9_quad_subdivision_isolated_quad", 4, 32, {9, 12, 4});
}

// F13 (Fig. 4.5, prose only): the "intermediate" quad-subdivision rule. Reconstruction: the maximal
// rule (F9 on an isolated quad) without the 2-loops of the 8 face darts on both sides, so that L
// matches a face of any surface and the face darts keep their outside 2-links; the added darts'
// 2-arcs are those computed for an isolated face. The thesis says it violates C_r(0,2) and breaks
// the constraint on non-isolated faces: the checker rejects C(0,2) only (I and O hold), the rule
// still yields a valid map on an isolated quad, and an invalid one on a face of the cube.
TEST(Fixtures, F13_IntermediateQuadRuleViolatesC02) {
  const Rule full = load("F9_quad_subdivision_isolated_quad");
  auto strip = [&](const DGraph& g) {
    DGraph out;
    for (Node v : g.nodes()) out.add_node(g.name(v));
    for (ArcId a : g.arc_slots()) {
      if (!g.arc_alive(a)) continue;
      const Arc& e = g.arc(a);
      const bool face_dart_loop = e.label == 2 && e.src == e.tgt && g.name(e.src)[0] == 'a';
      if (!face_dart_loop) out.add_arc(e.src, e.tgt, e.label);
    }
    return out;
  };
  const Rule r(strip(full.left()), strip(full.right()), 2, MapKind::GMap, "F13_intermediate");
  ASSERT_EQ(r.left().num_arcs() + 8, full.left().num_arcs());
  for (int i = 0; i <= 2; ++i) {
    EXPECT_TRUE(I(r, i)) << i;
    EXPECT_TRUE(O(r, i)) << i;
  }
  std::vector<Diagnostic> d;
  EXPECT_FALSE(check_cycle(r, 0, 2, d));
  EXPECT_FALSE(d.empty());
  EXPECT_FALSE(check_rule(r).ok());
  // Isolated quad: the outside 2-links are loops, the result is the maximal rule's.
  const Map h = apply_both(r, isolated_face(4), dart_by_index);
  EXPECT_TRUE(is_valid(h));
  EXPECT_EQ(h.size(), 32u);
  // A face of the cube: match a_k along the face of dart 0 (a0 = 0, a1 = alpha0(a0), a2 =
  // alpha1(a1)...).
  const Map cube = make_cube(2);
  std::vector<Dart> face{0};
  while (face.size() < 8) face.push_back(cube.alpha(face.size() % 2 == 1 ? 0 : 1, face.back()));
  ASSERT_EQ(cube.alpha(1, face[7]), face[0]);
  const Map hc =
      apply_both(r, cube, [&](const std::string& s) { return face[std::stoul(s.substr(1))]; });
  const auto rep = check_validity(hc);
  EXPECT_FALSE(rep.ok());
  bool c02 = false;
  for (const auto& v : rep.violations)
    c02 = c02 || (v.constraint == Constraint::Cycle && v.i == 0 && v.j == 2);
  EXPECT_TRUE(c02);
}

TEST(Fixtures, F11_VertexInsertionOnFreeEdge) {
  const Rule r = load("F11_vertex_insertion_free_edge");
  EXPECT_TRUE(check_rule(r).ok()) << to_text(check_rule(r));
  Map e(2);
  e.add_darts(2);
  e.link(0, 0, 1);
  const Map h = apply_both(r, e, [](const std::string& s) { return s == "a" ? Dart{0} : Dart{1}; });
  EXPECT_TRUE(is_valid(h));
  EXPECT_EQ(h.size(), 4u);
  const SemanticVerdict v = semantic_verdict(r, map_family(2, MapKind::GMap, 4));
  EXPECT_TRUE(v.applicable() && v.preserves);
}

TEST(Fixtures, F12_TriangulationOfIsolatedTriangle) {
  expect_on_isolated_face("F12_triangulation_isolated_triangle", 3, 18, {4, 6, 3});
}

TEST(Fixtures, Theorem2_VacuousCounterexample) {
  const Rule r = load("thm2_vacuous_3cycle");
  EXPECT_TRUE(I(r, 0));
  EXPECT_FALSE(O(r, 0));
  const SemanticVerdict v = semantic_verdict(r, map_family(1, MapKind::GMap, 6));
  EXPECT_FALSE(v.applicable());  // no G-map contains an oriented 3-cycle of 0-arcs
}

TEST(Fixtures, Def33_MultiplicityReading) {
  const Rule r = load("def33_multiplicity");
  EXPECT_FALSE(wI(r, 0));
  const SemanticVerdict v = semantic_verdict(r, map_family(1, MapKind::GMap, 4));
  EXPECT_TRUE(v.applicable());
  EXPECT_FALSE(v.preserves);
}

TEST(Fixtures, IdentityRuleThatAlgorithm3RejectsIsAccepted) {
  const Rule r = load("alg3_identity_on_0");
  EXPECT_TRUE(check_rule(r).ok());
  EXPECT_TRUE(semantic_verdict(r, map_family(2, MapKind::GMap, 4)).preserves);
}

TEST(Fixtures, OCompletionGap) {
  const Rule r = load("O_completion_gap");
  EXPECT_FALSE(check_rule(r, /*model_completion=*/false).ok());
  const CheckReport rep = check_rule(r);
  EXPECT_TRUE(rep.ok()) << to_text(rep);
  EXPECT_EQ(rep.count("C-O-completed"), 1u);
  const SemanticVerdict v = semantic_verdict(r, map_family(2, MapKind::GMap, 4));
  EXPECT_TRUE(v.applicable() && v.preserves);
}

TEST(Fixtures, OMapFaceSplit) {
  const Rule r = load("omap_face_split");
  const CheckReport rep = check_rule(r);
  EXPECT_TRUE(rep.ok()) << to_text(rep);
  const SemanticVerdict v = semantic_verdict(r, map_family(2, MapKind::OMap, 4));
  EXPECT_TRUE(v.applicable() && v.preserves);
}

TEST(Fixtures, ReportsAsTextAndJson) {
  const CheckReport rep = check_rule(load("F1_ex34_weak_incident"));
  EXPECT_FALSE(rep.ok());
  EXPECT_NE(to_text(rep).find("[I-added-node]"), std::string::npos);
  const auto j = to_json(rep);
  EXPECT_EQ(j["format"], "gmr.check");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["subject"], "rule");
  EXPECT_EQ(j["ok"], false);
  EXPECT_EQ(j["conditions"]["I(1)"], false);
  EXPECT_EQ(j["diagnostics"][0]["code"], "I-added-node");
}
