// Rule inference from before/after pairs (thesis §7.3): the κ joint graph, the split into L and R,
// hooks, the scheme checker; the thesis' triangle -> hexagon cases and the quad subdivision.
#include <gtest/gtest.h>

#include <utility>

#include "checker/check_format.hpp"
#include "checker/scheme_checker.hpp"
#include "inference/dart_mapping.hpp"
#include "inference/infer.hpp"
#include "inference/inference_format.hpp"
#include "inference/prior_cut.hpp"
#include "inference/rule_from_fold.hpp"
#include "inference/scheme_isomorphism.hpp"
#include "inference/tests/inference_support.hpp"
#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/sew.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"

using namespace gmr;
using namespace gmr::inference;
using namespace gmr::checker;
using namespace gmr::graph;
using namespace gmr::io;
using namespace gmr::scheme;
using namespace gmr::inference::test;

namespace {

// The after map of applying `s` at `hook` on a copy of g (the engine keeps preserved dart ids).
Map applied(const Map& g, const RuleScheme& s, Dart hook) {
  auto [h, app] = scheme::apply(SchemeEngine(s), std::as_const(g), {hook});
  EXPECT_TRUE(app.applied) << app.why;
  return h;
}

// `inferred` and `reference` applied at dart 0 of g give maps of the same signature; returns the
// one `inferred` gives.
Map applied_alike(const Map& g, const RuleScheme& inferred, const RuleScheme& reference) {
  Map mine = applied(g, inferred, 0);
  EXPECT_EQ(signature(mine), signature(applied(g, reference, 0)));
  return mine;
}

// The rules inferred from j, or from the pair (before, after) with the identity on dart ids, on
// one orbit type.
InferenceResult infer_on(const JointGraph& j, const OrbitType& orbit) {
  InferOptions opt;
  opt.orbit = orbit;
  return infer_rules(j, opt);
}
InferenceResult infer_on(const Map& before, const Map& after, const OrbitType& orbit) {
  return infer_on(joint_from_pair(before, after, identity_mapping(before, after)), orbit);
}

// Applies an inferred rule at its own hooks (the before darts of its hook nodes, orbit index 0).
Map apply_at_own_hooks(const Map& g, const InferredRule& r) {
  std::vector<Dart> hooks;
  for (uint32_t h : r.scheme.hook_nodes()) hooks.push_back(r.left_darts[h][0]);
  auto [out, app] = scheme::apply(SchemeEngine(r.scheme), std::as_const(g), hooks);
  EXPECT_TRUE(app.applied) << app.why;
  return out;
}

// Two free edges 2-sewn: 4 darts, 1-free.
Map sewn_edge() {
  Map g(2);
  g.add_darts(4);
  g.link(0, 0, 1);
  g.link(0, 2, 3);
  sew(g, 2, 0, 2);
  return g;
}

}  // namespace

// Thesis Fig. 7.15: triangle -> hexagon with the vertices preserved (edge split): a valid rule on
// <0,1,2>, L = n0, R = n0 <_,1,2> and the edge-midpoint node <1,_,2> 0-linked to it.
TEST(RuleInference, TriangleToHexagonEdgeSplitIsValid) {
  const Map tri = make_polygon(3), hex = make_polygon(6);
  const JointGraph j =
      joint_from_pair(tri, hex, read_mapping_file(data("triangle_hexagon_edge_split.json")));
  EXPECT_EQ(j.size(), 18u);
  const FoldResult f = fold(j, ot("<0,1,2>"), 0);
  ASSERT_TRUE(f.ok()) << f.failure.message;
  EXPECT_TRUE(instantiates_back(f, j));
  const InferredRule r = rule_from_fold(f, j);
  ASSERT_TRUE(r.accepted()) << r.reason;
  ASSERT_EQ(r.scheme.left.size(), 1u);
  ASSERT_EQ(r.scheme.right.size(), 2u);
  EXPECT_EQ(r.scheme.hooks, std::vector<std::string>{"n0"});
  EXPECT_EQ(r.scheme.right.nodes[0].name, "n0");
  EXPECT_EQ(r.scheme.right.nodes[0].label, ot("<_,1,2>"));
  EXPECT_EQ(r.scheme.right.nodes[1].label, ot("<1,_,2>"));
  // Applied to the triangle it gives the hexagon; applied to a square, an octagon.
  EXPECT_TRUE(is_isomorphic(apply_at_own_hooks(tri, r), hex));
  auto [oct, app] = scheme::apply(SchemeEngine(r.scheme), make_polygon(4), {0});
  ASSERT_TRUE(app.applied);
  EXPECT_TRUE(is_isomorphic(oct, make_polygon(8)));
}

// Thesis Fig. 7.15: the same objects with the edges preserved (vertex split) fold, but inserting an
// edge at every vertex is impossible on a closed surface: the checker rejects the new node (cycle
// condition C(0,2) at n1 <_,0,2>), and the driver reports no operation.
TEST(RuleInference, TriangleToHexagonVertexSplitIsRejectedByTheChecker) {
  const Map tri = make_polygon(3), hex = make_polygon(6);
  const JointGraph j =
      joint_from_pair(tri, hex, read_mapping_file(data("triangle_hexagon_vertex_split.json")));
  const FoldResult f = fold(j, ot("<0,1,2>"), 0);
  ASSERT_TRUE(f.ok()) << f.failure.message;
  EXPECT_TRUE(instantiates_back(f, j));
  const InferredRule r = rule_from_fold(f, j);
  EXPECT_EQ(r.verdict, RuleVerdict::Inconsistent);
  ASSERT_EQ(r.scheme.right.size(), 2u);
  EXPECT_EQ(r.scheme.right.nodes[1].label, ot("<_,0,2>"));
  EXPECT_FALSE(r.check.holds("C(0,2)"));
  bool on_n1 = false;
  for (const auto& d : r.check.diagnostics)
    if (d.severity == Severity::Error && d.side == graph::Side::R)
      for (const auto& n : d.nodes) on_n1 = on_n1 || n == "n1";
  EXPECT_TRUE(on_n1) << to_text(r.check);
  const InferenceResult res = infer_on(j, ot("<0,1,2>"));
  EXPECT_TRUE(res.rules.empty());
  ASSERT_EQ(res.attempts.size(), 1u);
  EXPECT_EQ(res.attempts[0].outcome, AttemptOutcome::Inconsistent);
}

// Quad subdivision inferred from the cube (48 darts) and its subdivision (192 darts, built by the
// library scheme and the engine, identity mapping on dart ids): the rule is the library's up to
// rule-scheme isomorphism, and applied to a torus and to a mesh read from OFF it agrees
// (signatures) with the library scheme's result.
TEST(RuleInference, QuadSubdivisionFromCubeIsTheLibraryScheme) {
  const RuleScheme lib = read_scheme_file(rule_file("quad_subdivision"));
  const Map cube = make_cube();
  const Map sub = applied(cube, lib, 0);
  ASSERT_EQ(sub.size(), 192u);
  const JointGraph j = joint_from_pair(cube, sub, identity_mapping(cube, sub));
  EXPECT_EQ(j.size(), 240u);
  const InferenceResult res = infer_on(j, ot("<0,1,2>"));
  ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
  const InferredRule& r = res.rules[0];
  EXPECT_EQ(r.scheme.left.size(), 1u);
  EXPECT_EQ(r.scheme.right.size(), 4u);
  EXPECT_TRUE(schemes_isomorphic(r.scheme, lib));
  EXPECT_TRUE(schemes_isomorphic(r.scheme, lib, {.exact_positions = true}));
  EXPECT_EQ(res.attempts.size(), 1u);  // one orbit: the whole cube
  EXPECT_TRUE(is_isomorphic(apply_at_own_hooks(cube, r), sub));
  const EmbeddedMap box = read_off_file(data("open_box.off"));
  for (const Map& g : {make_torus(5, 4), box.map, make_prism(7)}) {
    const Map mine = applied_alike(g, r.scheme, lib);
    EXPECT_EQ(mine.size(), 4 * g.size());
    EXPECT_TRUE(check_validity(mine).ok());
  }
}

// Every orbit type on the cube -> subdivided cube: the quad subdivision is among the rules, the
// rules are pairwise non-isomorphic, and each accepted rule applied at its own hooks on the cube
// gives back the subdivided cube (soundness of inference with the whole object as example).
TEST(RuleInference, AllOrbitTypesOnQuadSubdivision) {
  const RuleScheme lib = read_scheme_file(rule_file("quad_subdivision"));
  const Map cube = make_cube();
  const Map sub = applied(cube, lib, 0);
  const JointGraph j = joint_from_pair(cube, sub, identity_mapping(cube, sub));
  const InferenceResult res = infer_rules(j);
  ASSERT_FALSE(res.rules.empty());
  size_t lib_like = 0;
  for (size_t k = 0; k < res.rules.size(); ++k) {
    const InferredRule& r = res.rules[k];
    lib_like += schemes_isomorphic(r.scheme, lib);
    EXPECT_TRUE(r.check.ok());
    EXPECT_TRUE(is_isomorphic(apply_at_own_hooks(cube, r), sub)) << r.orbit.str();
    for (size_t l = k + 1; l < res.rules.size(); ++l)
      EXPECT_FALSE(schemes_isomorphic(r.scheme, res.rules[l].scheme));
  }
  EXPECT_EQ(lib_like, 1u);
  // <> folds into one node per dart: 48 L nodes, 192 R nodes.
  bool empty_orbit = false;
  for (const auto& a : res.attempts)
    if (a.orbit.size() == 0) {
      empty_orbit = true;
      EXPECT_EQ(a.left_nodes, 48u);
      EXPECT_EQ(a.right_nodes, 192u);
    }
  EXPECT_TRUE(empty_orbit);
  EXPECT_NE(to_text(res).find("rule(s) inferred"), std::string::npos);
}

// Marking (thesis §7.3.2) and de-duplication: vertex insertion on every edge of an open square,
// inferred on <0,2>. The square is the whole example, so L folds into its 4 edges (n0 and n3 with
// a full decoration, n1 and n2 <_,2>): not the library's one-edge scheme (thesis §7.6: the example
// is not representative of a single edge). The start darts of n0 and n3 are marked after the first
// fold; the next unmarked dart (in n1) gives the same rule rooted elsewhere, merged as a duplicate.
TEST(RuleInference, MarkingSkipsEquivalentStartsAndDuplicatesAreMerged) {
  const RuleScheme vi = read_scheme_file(rule_file("vertex_insertion"));
  Map g = make_polygon(4);
  Map h = g;
  for (Dart e : {Dart{0}, Dart{2}, Dart{4}, Dart{6}}) {
    auto app = scheme::apply(SchemeEngine(vi), h, {e});
    ASSERT_TRUE(app.applied) << app.why;
  }
  const InferenceResult res = infer_on(g, h, ot("<0,2>"));
  ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
  const RuleScheme& s = res.rules[0].scheme;
  EXPECT_EQ(s.left.size(), 4u);
  EXPECT_EQ(s.right.size(), 8u);
  EXPECT_FALSE(schemes_isomorphic(s, vi));
  ASSERT_EQ(res.attempts.size(), 2u) << to_text(res);
  EXPECT_EQ(res.attempts[1].outcome, AttemptOutcome::Duplicate);
  EXPECT_EQ(res.attempts[1].rule, 0);
  EXPECT_EQ(res.duplicates[0], 1u);
  EXPECT_TRUE(is_isomorphic(apply_at_own_hooks(g, res.rules[0]), h));
}

TEST(DartMapping, FileErrorsAreLocated) {
  const Map tri = make_polygon(3), hex = make_polygon(6);
  EXPECT_THROW(parse_mapping(R"({"format":"gmr.mapping","version":1,"pairs":[[0]]})"), Error);
  EXPECT_THROW(parse_mapping(R"({"format":"gmr.map","version":1})"), Error);
  try {
    joint_from_pair(tri, hex,
                    parse_mapping(R"({"format":"gmr.mapping","version":1,"pairs":[[0,0],[1,0]]})"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location(), "pairs[1]");
    EXPECT_NE(e.message().find("image of two darts"), std::string::npos);
  }
  EXPECT_THROW(joint_from_pair(tri, hex, DartMapping{{{6, 0}}, {}, {}, {}}), Error);
}

// Orbit pairs are expanded with Alg. 5: the hexagon's face paired with the triangle's... is not
// isomorphic; a square's face paired with a relabeled square face is.
TEST(DartMapping, OrbitPairsExpandByOrbitIsomorphism) {
  const Map a = make_polygon(4), b = make_polygon(4);
  DartMapping m = parse_mapping(R"({"format":"gmr.mapping","version":1,
      "orbits":[{"before":0,"after":3,"orbit":"<0,1>","after_orbit":"<0,1>"}]})");
  const auto pairs = expand_mapping(a, b, m);
  ASSERT_EQ(pairs.size(), 8u);
  for (auto [x, y] : pairs)
    EXPECT_EQ(b.alpha(0, y), [&] {
      for (auto [x2, y2] : pairs)
        if (x2 == a.alpha(0, x)) return y2;
      return kNoDart;
    }());
  EXPECT_THROW(expand_mapping(make_polygon(3), make_polygon(6), m), Error);
  const std::string text = mapping_to_json_text(m);
  EXPECT_EQ(parse_mapping(text).orbits.size(), 1u);
}

// "Likewise for every library operation that has an example": each library scheme with one hook is
// applied to an example whose hook orbit is the whole object, then inferred back on the scheme's
// orbit type with the identity mapping. Examples with free cells (a single polygon, a free edge)
// carry loops on preserved darts, which the inferred rule would demand (thesis §7.6); the
// posterior-cut loops of those dimensions give the library scheme back, up to isomorphism, and so
// do the prior-cut loops (cut from the example before folding). The
// result is also applied to another object and compared with the library's (signatures).
TEST(RuleInference, LibrarySchemesAreRecoveredFromTheirExamples) {
  struct Case {
    const char* rule;
    Map example;
    DimMask cut;
    Map other;
    DimMask explicit_loops = 0;
  };
  const std::vector<Case> cases = {
      {"quad_subdivision", make_cube(), 0, make_torus(4, 3)},
      {"loop_subdivision", make_tetrahedron(), 0, make_cube()},
      {"loop_subdivision", make_polygon(3), 0, make_tetrahedron()},  // Loop topology: triangle -> 4
      {"quad_subdivision", make_polygon(4), 0, make_cube()},
      {"edge_triangulation", make_tetrahedron(), 0, make_prism(5)},
      {"doo_sabin_subdivision", make_cube(), 0, make_prism(5)},
      {"sqrt3_subdivision", make_tetrahedron(), 0,
       make_square_pyramid()},  // not all triangles: still applies
      {"face_triangulation", make_polygon(5), 1u << 2, make_polygon(7)},
      {"face_extrusion", make_polygon(4), 1u << 2, make_polygon(3)},
      {"vertex_insertion", make_free_edge(), 1u << 1, make_free_edge()},
      // On a free edge, n0's 2-loops could be read as an implicit 1 (aggressive: <0,1>, not the
      // library's <0,_>), and explicit 1-loops (conservative) would also make n1's implicit 1-loops
      // explicit: no loop policy fits both nodes (thesis §7.2.5, "a more representative example").
      // Two free edges 2-sewn are that example.
      {"dual_vertex_insertion", sewn_edge(), 1u << 1, make_free_edge()},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.rule);
    const RuleScheme lib = read_scheme_file(rule_file(c.rule));
    const Map after = applied(c.example, lib, 0);
    const JointGraph j = joint_from_pair(c.example, after, identity_mapping(c.example, after));
    InferOptions opt;
    opt.orbit = lib.orbit;
    opt.rule.cut_loops = c.cut;
    opt.fold.loops.explicit_loops = c.explicit_loops;
    const InferenceResult res = infer_rules(j, opt);
    ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
    const RuleScheme& s = res.rules[0].scheme;
    EXPECT_TRUE(schemes_isomorphic(s, lib)) << scheme_to_json_text(s);
    auto [mine, a1] = scheme::apply(SchemeEngine(s), std::as_const(c.other), {0});
    auto [theirs, a2] = scheme::apply(SchemeEngine(lib), std::as_const(c.other), {0});
    ASSERT_EQ(a1.applied, a2.applied) << a1.why << a2.why;
    if (a1.applied) {
      EXPECT_EQ(signature(mine), signature(theirs));
    }
    if (c.cut) {  // without the cut, the rule keeps its explicit loops: not the library's
      // Prior-cut loops (prior_cut.hpp): the same loops cut from the example instead of the rule.
      JointGraph cut = j;
      EXPECT_GT(cut_prior_loops(cut, c.cut), 0u);
      opt.rule.cut_loops = 0;
      const InferenceResult prior = infer_rules(cut, opt);
      ASSERT_EQ(prior.rules.size(), 1u) << to_text(prior);
      EXPECT_TRUE(schemes_isomorphic(prior.rules[0].scheme, lib))
          << scheme_to_json_text(prior.rules[0].scheme);
      const InferenceResult raw = infer_rules(j, opt);
      ASSERT_EQ(raw.rules.size(), 1u);
      EXPECT_FALSE(schemes_isomorphic(raw.rules[0].scheme, lib));
    }
  }
}

// Powell–Sabin 6-split (thesis §7.4, a Jerboa rule inferred from an example): the after object is
// built by applying library operations in sequence — vertex insertion on each edge of a triangle,
// then face triangulation of the resulting hexagon (6 -> 36 darts). Inferred on <0,1,2>, the rule
// has 6 R nodes; it is the library's barycentric "edge triangulation" up to rule-scheme
// isomorphism, and applied to a unit square, a quad grid and a tetrahedron it agrees with it
// (signatures).
TEST(RuleInference, PowellSabinSixSplitFromLibraryOperationsInSequence) {
  const RuleScheme vi = read_scheme_file(rule_file("vertex_insertion"));
  const RuleScheme ft = read_scheme_file(rule_file("face_triangulation"));
  const RuleScheme et = read_scheme_file(rule_file("edge_triangulation"));
  const Map tri = make_polygon(3);
  Map after = tri;
  for (Dart e : {Dart{0}, Dart{2}, Dart{4}})
    ASSERT_TRUE(scheme::apply(SchemeEngine(vi), after, {e}).applied);
  ASSERT_TRUE(scheme::apply(SchemeEngine(ft), after, {0}).applied);
  ASSERT_EQ(after.size(), 36u);
  const InferenceResult res = infer_on(tri, after, ot("<0,1,2>"));
  ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
  const RuleScheme& ps = res.rules[0].scheme;
  EXPECT_EQ(ps.left.size(), 1u);
  EXPECT_EQ(ps.right.size(), 6u);
  EXPECT_TRUE(schemes_isomorphic(ps, et)) << scheme_to_json_text(ps);
  for (const Map& g : {make_grid(1, 1), make_grid(3, 2), make_tetrahedron()}) {
    EXPECT_EQ(applied_alike(g, ps, et).size(), 6 * g.size());
  }
}

// Plurality of answers (thesis §7.2.5 and §7.6): on a free edge, dual-vertex insertion needs an
// explicit loop at n0 and an implicit one at n1, which no loop policy gives (see above). Folding
// every combination of consistent relabelings (fold_all) finds it: one of the inferred rules, with
// the 1-loops of preserved nodes cut, is the library scheme.
TEST(RuleInference, EnumeratingRelabelingsFindsMixedLoopReadings) {
  const RuleScheme lib = read_scheme_file(rule_file("dual_vertex_insertion"));
  const Map edge = make_free_edge();
  const Map after = applied(edge, lib, 0);
  const JointGraph j = joint_from_pair(edge, after, identity_mapping(edge, after));
  const FoldAll all = fold_all(j, lib.orbit, 0);
  EXPECT_FALSE(all.truncated);
  ASSERT_GE(all.folds.size(), 2u);
  for (const auto& f : all.folds) EXPECT_TRUE(instantiates_back(f, j));
  EXPECT_EQ(all.choices[0], std::vector<uint32_t>(all.choices[0].size(), 0));  // the default first
  InferOptions opt;
  opt.orbit = lib.orbit;
  opt.rule.cut_loops = 1u << 1;
  EXPECT_FALSE(schemes_isomorphic(infer_rules(j, opt).rules.at(0).scheme, lib));
  opt.all_relabelings = true;
  const InferenceResult res = infer_rules(j, opt);
  size_t found = 0;
  for (const auto& r : res.rules) found += schemes_isomorphic(r.scheme, lib);
  EXPECT_EQ(found, 1u) << to_text(res);
  EXPECT_GE(res.rules.size(), 2u);
}

// Selections (thesis §7.1.2, local operations): vertex insertion applied to ONE edge of a square.
// Without a selection the example is the whole square (L = 4 nodes); with the edge's 2 darts
// selected before and its 4 darts after (tests/data/square_one_edge_selection.json), the 1-links
// to the rest of the square become undefined neighbours and the library scheme comes back.
TEST(RuleInference, SelectionInfersALocalOperation) {
  const RuleScheme vi = read_scheme_file(rule_file("vertex_insertion"));
  const Map sq = make_polygon(4);
  const Map after = applied(sq, vi, 0);
  ASSERT_EQ(after.size(), 10u);
  const InferenceResult whole = infer_on(sq, after, ot("<0,2>"));
  ASSERT_EQ(whole.rules.size(), 1u);
  EXPECT_EQ(whole.rules[0].scheme.left.size(), 4u);
  const DartMapping m = read_mapping_file(data("square_one_edge_selection.json"));
  const JointGraph j = joint_from_pair(sq, after, m);
  EXPECT_EQ(j.size(), 6u);
  const InferenceResult local = infer_on(j, ot("<0,2>"));
  ASSERT_EQ(local.rules.size(), 1u) << to_text(local);
  EXPECT_TRUE(schemes_isomorphic(local.rules[0].scheme, vi))
      << scheme_to_json_text(local.rules[0].scheme);
  // A mapped dart outside the selection is refused.
  DartMapping bad = m;
  bad.pairs.emplace_back(2, 2);
  EXPECT_THROW(joint_from_pair(sq, after, bad), Error);
}

// Doo–Sabin iterations 1, 2, 3, each inferred directly from iteration 0 (thesis §7.4.3): the after
// object is the cube subdivided k times by the library's Doo–Sabin scheme
// (tools/data/rules/doo_sabin_subdivision.json); the engine keeps the ids of preserved darts, so
// the identity mapping relates iteration 0 and iteration k. R has 4, 16, 64 nodes on the closed
// cube; iteration 1 is the scheme itself; applied to a tetrahedron, the inferred iteration-k rule
// equals k Doo–Sabin steps.
TEST(RuleInference, DooSabinIterationsFromIterationZero) {
  const RuleScheme ds = read_scheme_file(rule_file("doo_sabin_subdivision"));
  ASSERT_TRUE(check_scheme(ds).ok());
  const Map cube = make_cube();
  Map after = cube, tetra_k = make_tetrahedron();
  size_t nodes = 1;
  for (int k = 1; k <= 3; ++k) {
    SCOPED_TRACE(k);
    ASSERT_TRUE(scheme::apply(SchemeEngine(ds), after, {0}).applied);
    ASSERT_TRUE(scheme::apply(SchemeEngine(ds), tetra_k, {0}).applied);
    nodes *= 4;
    const InferenceResult res = infer_on(cube, after, ot("<0,1,2>"));
    ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
    const RuleScheme& r = res.rules[0].scheme;
    EXPECT_EQ(r.left.size(), 1u);
    EXPECT_EQ(r.right.size(), nodes);
    EXPECT_EQ(schemes_isomorphic(r, ds), k == 1);
    auto [got, app] = scheme::apply(SchemeEngine(r), make_tetrahedron(), {0});
    ASSERT_TRUE(app.applied);
    EXPECT_EQ(signature(got), signature(tetra_k));
  }
}

// Kobbelt √3 (thesis §7.4.2, a single-step rule with edge flips): inferred from a tetrahedron
// (24 -> 72 darts) subdivided by the library's √3 scheme (tools/data/rules/sqrt3_subdivision.json):
// L1 + R3, the library scheme itself (rule-scheme isomorphism); applied to a closed triangle mesh
// (the cube with every face triangulated by the library's face triangulation) it triples the face
// count, and agrees with the scheme (signatures).
TEST(RuleInference, KobbeltSqrt3FromATetrahedron) {
  const RuleScheme s3 = read_scheme_file(rule_file("sqrt3_subdivision"));
  ASSERT_TRUE(check_scheme(s3).ok());
  const Map tet = make_tetrahedron();
  const Map after = applied(tet, s3, 0);
  ASSERT_EQ(after.size(), 72u);
  const InferenceResult res = infer_on(tet, after, ot("<0,1,2>"));
  ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
  const RuleScheme& r = res.rules[0].scheme;
  EXPECT_EQ(r.right.size(), 3u);
  EXPECT_TRUE(schemes_isomorphic(r, s3)) << scheme_to_json_text(r);
  const RuleScheme ft = read_scheme_file(rule_file("face_triangulation"));
  Map mesh = make_cube();
  for (Dart f : orbit_representatives(mesh, ot("<0,1>")))
    ASSERT_TRUE(scheme::apply(SchemeEngine(ft), mesh, {f}).applied);
  ASSERT_EQ(count_cells(mesh, 2), 24u);
  const Map mine = applied_alike(mesh, r, s3);
  EXPECT_TRUE(check_validity(mine).ok());
  EXPECT_EQ(count_cells(mine, 2), 72u);
}

namespace {

// Two copies of g side by side (the second's darts shifted by g's capacity): two free cells for
// the sewing operations' two hooks.
Map two_copies(const Map& g) {
  Map u(g.dimension());
  u.add_darts(2 * g.capacity());
  const Dart off = g.capacity();
  for (int i = 0; i <= g.dimension(); ++i)
    for (Dart d = 0; d < g.capacity(); ++d)
      if (g.alpha(i, d) > d) {
        u.link(i, d, g.alpha(i, d));
        u.link(i, d + off, g.alpha(i, d) + off);
      }
  return u;
}

struct HookedExample {
  Map before, after;
  DartMapping mapping;
};

InferenceResult infer_on(const RuleScheme& lib, const HookedExample& e, DimMask cut) {
  const JointGraph j = joint_from_pair(e.before, e.after, e.mapping);
  InferOptions opt;
  opt.orbit = lib.orbit;
  opt.rule.cut_loops = cut;
  return infer_rules(j, opt);
}

}  // namespace

// The sewing operations (thesis Fig. 3.19a): sew2 and sew3 have two hooks, so the joint graph of
// two free cells sewn has one L component per hook (n0, n1, the second hooked at its
// full-decoration node); unsew2/unsew3 one hook, L connected by the sewn link. The examples are the
// smallest: two free edges (n = 2) and two triangles (n = 3, 3-free), so the preserved darts carry
// loops of the dimensions outside the orbit and the sewing dimension (1 for edges, 2 for faces);
// the library leaves those out, so they are cut (posterior cut), and without the cut they stay
// explicit.
TEST(RuleInference, SewingSchemesAreRecoveredFromTwoCellsSewn) {
  struct Case {
    const char* rule;
    Map before;
    std::vector<Dart> hooks;
    DimMask cut;
    size_t hooks_inferred;
  };
  const Map edges = two_copies(make_free_edge()), triangles = two_copies(make_polygon(3, 3));
  Map sewn_triangles = triangles;
  sew(sewn_triangles, 3, 0, 6);
  const std::vector<Case> cases = {
      {"sew2", edges, {0, 2}, 1u << 1, 2},
      {"unsew2", sewn_edge(), {0}, 1u << 1, 1},
      {"sew3", triangles, {0, 6}, 1u << 2, 2},
      {"unsew3", sewn_triangles, {0}, 1u << 2, 1},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.rule);
    const RuleScheme lib = read_scheme_file(rule_file(c.rule));
    auto [after, app] = scheme::apply(SchemeEngine(lib), std::as_const(c.before), c.hooks);
    ASSERT_TRUE(app.applied) << app.why;
    const HookedExample e{c.before, after, identity_mapping(c.before, after)};
    const InferenceResult res = infer_on(lib, e, c.cut);
    ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
    const InferredRule& r = res.rules[0];
    EXPECT_EQ(r.scheme.hooks.size(), c.hooks_inferred);
    EXPECT_TRUE(schemes_isomorphic(r.scheme, lib)) << scheme_to_json_text(r.scheme);
    EXPECT_TRUE(is_isomorphic(apply_at_own_hooks(c.before, r), after));
    const InferenceResult raw = infer_on(lib, e, 0);
    ASSERT_EQ(raw.rules.size(), 1u);
    EXPECT_FALSE(schemes_isomorphic(raw.rules[0].scheme, lib));
  }
}

namespace {
// A local example (thesis §7.1.2): the hook's <o>-orbit, the darts 1-linked to it (when
// with_neighbours) and, after, the preserved ones among them plus the created darts.
HookedExample local_example(const Map& before, const RuleScheme& lib, Dart hook, const OrbitType& o,
                            bool with_neighbours) {
  auto [after, app] = scheme::apply(SchemeEngine(lib), std::as_const(before), {hook});
  EXPECT_TRUE(app.applied) << app.why;
  std::vector<Dart> sel = orbit(before, o, hook);
  if (with_neighbours) {
    const size_t k = sel.size();
    for (size_t i = 0; i < k; ++i) sel.push_back(before.alpha(1, sel[i]));
  }
  DartMapping m;
  std::vector<Dart> after_sel;
  for (Dart d : sel)
    if (after.alive(d)) {
      m.pairs.emplace_back(d, d);
      after_sel.push_back(d);
    }
  for (Dart d = before.capacity(); d < after.capacity(); ++d)
    if (after.alive(d)) after_sel.push_back(d);
  m.before_selection = sel;
  m.after_selection = after_sel;
  return {before, after, m};
}
}  // namespace

// Local operations through selections (thesis §7.1.2, docs/inference.md): edge collapse and edge
// deletion applied to one edge of a closed surface, with the edge's 4 darts and their 4
// 1-neighbours selected before and those neighbours after; vertex insertion on <2> with the edge's
// 4 darts selected before and those plus the 4 created darts after. Links to unselected darts are
// undefined neighbours, which gives n1 <_,_> (collapse, deletion) and no 1-arc at x and y
// (insertion). The inferred rule is the library's; the other starts (the neighbours, whose hook
// orbit is cut by the selection) fail. Applied to a prism it agrees with the library (signatures).
TEST(RuleInference, LocalLibrarySchemesAreRecoveredThroughSelections) {
  for (const char* rule : {"edge_collapse", "edge_deletion", "vertex_insertion_folded_2"}) {
    SCOPED_TRACE(rule);
    const RuleScheme lib = read_scheme_file(rule_file(rule));
    const bool neighbours = std::string(rule) != "vertex_insertion_folded_2";
    for (const Map& g : {make_tetrahedron(), make_cube()}) {
      const HookedExample e = local_example(g, lib, 0, ot("<0,2>"), neighbours);
      EXPECT_EQ(e.mapping.before_selection->size(), 8u - (neighbours ? 0 : 4));
      const InferenceResult res = infer_on(lib, e, 0);
      ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
      const RuleScheme& s = res.rules[0].scheme;
      EXPECT_TRUE(schemes_isomorphic(s, lib)) << scheme_to_json_text(s);
      EXPECT_EQ(res.attempts.size(), neighbours ? 5u : 1u) << to_text(res);
      for (size_t k = 1; k < res.attempts.size(); ++k) {
        EXPECT_EQ(res.attempts[k].outcome, AttemptOutcome::FoldFailed);
        EXPECT_NE(res.attempts[k].reason.find("partial hook orbit"), std::string::npos);
      }
      applied_alike(make_prism(5), s, lib);
    }
  }
}
