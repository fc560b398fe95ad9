// The (2,2,2)-Menger operation (inference paper §9.2.2: a cube becomes a polycube of genus 28 with
// 81 volumes, and 270 faces and 216 vertices on its boundary surface; no algorithmic definition or
// rule of it is known), inferred from two glued cubes on <0,1,2,3> as Menger level 1 (thesis
// §7.4.4): R has 81 nodes (7776 after darts / 96 darts in the hook orbit). Applied to other
// polycubes, it gives the polycube of their (2,2,2)-Menger voxels (signatures). Its position
// expressions are then inferred (thesis Ch. 8) with the voxels as unit cubes and the pattern on the
// 5 x 5 x 5 grid.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <utility>

#include "inference/expression_inference.hpp"
#include "inference/infer.hpp"
#include "inference/inference_format.hpp"
#include "inference/tests/inference_support.hpp"
#include "inference/tests/polycube_support.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/scheme/scheme_engine.hpp"

using namespace gmr;
using namespace gmr::inference;
using namespace gmr::scheme;
namespace pc = gmr::inference::test::polycube;

namespace {

const std::vector<Voxel> kGluedCubes{{0, 0, 0}, {0, 0, 1}};

pc::PolycubeSubdivision menger222(const std::vector<Voxel>& cubes) {
  return pc::PolycubeSubdivision(cubes, menger_polycube_voxels(2, 2, 2), 5);
}

RuleScheme infer_menger222() {
  const pc::PolycubeSubdivision ex = menger222(kGluedCubes);
  InferOptions opt;
  opt.orbit = OrbitType::range(0, 3);
  const InferenceResult res = infer_rules(joint_from_pair(ex.before, ex.after, ex.mapping), opt);
  if (res.rules.size() != 1) ADD_FAILURE() << to_text(res);
  return res.rules.at(0).scheme;
}

// Positions carried from `source` to `target` through the isomorphism that sends dart `t` to `s`
// (Algorithm 1's BFS labelings from both darts; the words must agree).
EmbeddedMap carry_positions(const EmbeddedMap& source, Dart s, const Map& target, Dart t) {
  EXPECT_EQ(bfs_word(source.map, s), bfs_word(target, t));
  const std::vector<Dart> ls = bfs_labeling(source.map, s), lt = bfs_labeling(target, t);
  EmbeddedMap out;
  out.map = target;
  out.fields.push_back(EmbeddingField::numeric("position", OrbitType{1, 2, 3}));
  const auto& from = source.fields[0].values;
  std::vector<bool> done(target.capacity(), false);
  for (size_t k = 0; k < lt.size(); ++k) {
    if (done[lt[k]]) continue;
    out.fields[0].values.set(target, lt[k], from.get(ls[k]));
    for (Dart e : orbit(target, OrbitType{1, 2, 3}, lt[k])) done[e] = true;
  }
  return out;
}

}  // namespace

TEST(RuleInference, MengerPolycube222FromTwoGluedCubes) {
  const pc::PolycubeSubdivision ex = menger222(kGluedCubes);
  ASSERT_EQ(ex.before.size(), 96u);
  ASSERT_EQ(ex.after.size(), 2 * 81 * 48u);
  const RuleScheme m = infer_menger222();
  EXPECT_EQ(m.left.size(), 1u);
  EXPECT_EQ(m.right.size(), 81u);
  // On one cube: the paper's polycube (81 volumes; 270 faces and 216 vertices on its boundary).
  auto [one, app1] = scheme::apply(SchemeEngine(m), make_polycube({{0, 0, 0}}), {0});
  ASSERT_TRUE(app1.applied) << app1.why;
  EXPECT_TRUE(check_validity(one).ok());
  EXPECT_EQ(count_cells(one, 3), 81u);
  EXPECT_EQ(count_boundary_cells(one), 270u);
  EXPECT_EQ(count_cells(one, 0), 216u);
  EXPECT_EQ(signature(one), signature(make_polycube(menger_polycube_voxels(2, 2, 2))));
  // On an L-shaped tricube: the polycube of its (2,2,2)-Menger voxels, built voxel by voxel.
  const std::vector<Voxel> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto [got, app3] = scheme::apply(SchemeEngine(m), make_polycube(tri), {0});
  ASSERT_TRUE(app3.applied) << app3.why;
  EXPECT_TRUE(check_validity(got).ok());
  EXPECT_EQ(got.size(), 3 * 81 * 48u);
  EXPECT_EQ(signature(got), signature(menger222(tri).after));
}

TEST(ExpressionInference, MengerPolycube222Positions) {
  const pc::PolycubeSubdivision ex = menger222(kGluedCubes);
  const RuleScheme m = infer_menger222();
  const EmbeddedMap before = pc::with_positions(ex.before, ex.cubes, 1.0);
  // The object after as the engine numbers it: the topological result, with the positions of the
  // polycube built voxel by voxel (side 1/5) carried over by the isomorphism fixing the hook.
  auto [topo, app] = scheme::apply(SchemeEngine(m), std::as_const(ex.before), {0});
  ASSERT_TRUE(app.applied) << app.why;
  const EmbeddedMap after = carry_positions(pc::with_positions(ex.after, ex.sub, 0.2),
                                            ex.mapping.pairs[0].second, topo, 0);
  const ExpressionInference inf = infer_expressions(m, before, {0}, after);
  size_t kept = 0, solved = 0;
  const std::regex fraction(R"(\((-?\d+)/(\d+)\))");
  std::set<std::string> weights;
  for (const auto& n : inf.nodes) {
    ASSERT_NE(n.status, InferredExpression::Status::NoSolution) << n.node;
    kept += n.status == InferredExpression::Status::Kept;
    if (n.status != InferredExpression::Status::Solved) continue;
    ++solved;
    EXPECT_EQ(n.code.find("vector("), std::string::npos)
        << n.node << ": " << n.code;  // no translation
    for (std::sregex_iterator it(n.code.begin(), n.code.end(), fraction), end; it != end; ++it) {
      EXPECT_EQ((*it)[2], "5") << n.node << ": "
                               << n.code;  // weights in fifths: the 5 x 5 x 5 grid
      weights.insert((*it)[0]);
    }
    std::cout << "[ infer    ] " << n.node << ": " << n.code << "\n";
  }
  EXPECT_EQ(kept, 1u);  // the corner voxel's node keeps the cube's vertices
  // One expression per vertex of the 6 x 6 x 6 grid up to the cube's 48 symmetries (coordinates
  // min(i, 5 - i) in {0, 1, 2}, sorted: 10 classes), the corner being kept.
  EXPECT_EQ(solved, 9u);
  EXPECT_FALSE(weights.empty());
  // The inferred expressions reproduce the object after, and on a single cube give the pattern.
  EmbeddedMap again = before;
  {
    const expr::CompiledScheme cs = expr::compile_scheme(inf.scheme);
    expr::EmbeddingPropagation p(cs, again);
    ASSERT_TRUE(scheme::apply(SchemeEngine(inf.scheme), again.map, {0}, &p));
    EXPECT_EQ(p.issue_count(), 0u);
  }
  const auto& a = again.find("position")->values;
  const auto& b = after.find("position")->values;
  for (Dart d = 0; d < after.map.capacity(); ++d)
    if (after.map.alive(d)) {
      for (size_t c = 0; c < 3; ++c) ASSERT_NEAR(a.get(d)[c], b.get(d)[c], 1e-12) << "dart " << d;
    }
}
