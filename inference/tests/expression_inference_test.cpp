// Inference of affine position expressions (inference/expression_inference.hpp, thesis Ch. 8):
// the object after is produced by gmr from a scheme with known expressions, the expressions are
// stripped, and the inference must find expressions that reproduce the object after (and, where
// the thesis says so, the known ones: vertex insertion's midpoint, quad subdivision's edge and
// face points).
#include "inference/expression_inference.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"

using namespace gmr;
using namespace gmr::inference;
using Status = InferredExpression::Status;

namespace {

std::string source(const std::string& rel) {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/" + rel;
}

EmbeddedMap load(const std::string& off) { return io::read_off_file(source(off)); }

// The object after: `s` (with its expressions) applied at `hook`.
EmbeddedMap apply(const scheme::RuleScheme& s, EmbeddedMap m, Dart hook) {
  const expr::CompiledScheme cs = expr::compile_scheme(s);
  expr::EmbeddingPropagation p(cs, m);
  EXPECT_TRUE(scheme::apply(scheme::SchemeEngine(s), m.map, {hook}, &p));
  EXPECT_EQ(p.issue_count(), 0u);
  return m;
}

scheme::RuleScheme without_expressions(scheme::RuleScheme s) {
  for (auto& n : s.right.nodes) n.expressions.clear();
  return s;
}

// Re-applying the inferred scheme to the object before gives the object after's positions.
void expect_reproduces(const ExpressionInference& inf, const EmbeddedMap& before,
                       const EmbeddedMap& after, Dart hook) {
  const EmbeddedMap again = apply(inf.scheme, before, hook);
  const auto& a = again.find("position")->values;
  const auto& b = after.find("position")->values;
  for (Dart d = 0; d < after.map.capacity(); ++d) {
    if (!after.map.alive(d)) continue;
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(a.get(d)[c], b.get(d)[c], 1e-12) << "dart " << d;
  }
}

// `s` applied at dart 0 of the cube, and the expressions inferred back from the objects before and
// after.
struct CubeInference {
  EmbeddedMap before, after;
  ExpressionInference inf;
};
CubeInference infer_on_cube(const scheme::RuleScheme& s) {
  CubeInference c{load("tools/data/cube.off"), {}, {}};
  c.after = apply(s, c.before, 0);
  c.inf = infer_expressions(without_expressions(s), c.before, {0}, c.after);
  return c;
}

const InferredExpression& node(const ExpressionInference& inf, const std::string& name) {
  for (const auto& n : inf.nodes)
    if (n.node == name) return n;
  throw std::runtime_error("no node " + name);
}

}  // namespace

TEST(ExpressionInference, VertexInsertionMidpoint) {
  const scheme::RuleScheme s =
      io::read_scheme_file(source("tools/data/rules/vertex_insertion.json"));
  const auto [before, after, inf] = infer_on_cube(s);
  EXPECT_EQ(node(inf, "n0").status, Status::Kept);
  ASSERT_EQ(node(inf, "n1").status, Status::Solved);
  EXPECT_EQ(node(inf, "n1").code, "middle(<0>_position(n0))");
  expect_reproduces(inf, before, after, 0);
}

TEST(ExpressionInference, QuadSubdivisionEdgeAndFacePoints) {
  // Quad subdivision with the linear positions of the thesis (Fig. 6.15): edge midpoints and face
  // barycentres, old vertices kept.
  scheme::RuleScheme s = io::read_scheme_file(source("tools/data/rules/quad_subdivision.json"));
  s.right.nodes[0].expressions.clear();
  s.right.nodes[1].expressions[0].code = "middle(<0>_position(n0))";
  const auto [before, after, inf] = infer_on_cube(s);
  EXPECT_EQ(node(inf, "n0").status, Status::Kept);
  ASSERT_EQ(node(inf, "n1").status, Status::Solved);
  EXPECT_EQ(node(inf, "n1").code, "middle(<0>_position(n0))");
  EXPECT_EQ(node(inf, "n2").status, Status::Inherited);  // same vertex class as n1
  ASSERT_EQ(node(inf, "n3").status, Status::Solved);
  EXPECT_EQ(node(inf, "n3").code, "middle(<0,1>_position(n0))");
  EXPECT_FALSE(node(inf, "n3").unique);  // on one closed cube, other combinations also fit
  expect_reproduces(inf, before, after, 0);
}

TEST(ExpressionInference, CatmullClarkOnTheCubeIsReproducedNotRecovered) {
  // The Catmull-Clark vertex point reads all the edges and faces around the vertex, which no
  // point of interest of n0 gives: the inferred expression reproduces the cube's result with the
  // symmetric points it has (thesis §8.4: inferred expressions are not unique and may differ from
  // the ground truth).
  const scheme::RuleScheme s =
      io::read_scheme_file(source("tools/data/rules/quad_subdivision.json"));
  const auto [before, after, inf] = infer_on_cube(s);
  for (const auto& n : inf.nodes) std::cout << "[ infer    ] " << n.node << ": " << n.code << "\n";
  ASSERT_EQ(node(inf, "n0").status, Status::Solved);
  expect_reproduces(inf, before, after, 0);
}

TEST(ExpressionInference, NoSolutionIsReported) {
  // Face points pushed along the first edge of each face (in the scheme's dart order): no affine
  // combination of the points of interest gives them on the cube.
  scheme::RuleScheme s = io::read_scheme_file(source("tools/data/rules/quad_subdivision.json"));
  s.right.nodes[3].expressions[0].code =
      "middle(<0,1>_position(n0)) + 0.1 * (n0@0.position - n0.position)";
  const auto [before, after, inf] = infer_on_cube(s);
  EXPECT_EQ(node(inf, "n3").status, Status::NoSolution);
  EXPECT_EQ(node(inf, "n1").status, Status::Solved);
}
