// Expression inference on the von Koch curve (thesis §8.4, Fig. 8.18): the case where the
// inferred expression reproduces the example and fails from the second iteration on.
//
// The object is a flat square "pillow" (two faces sharing their four edges, a closed 2-G-map) and
// the topology is one Koch step on every edge (inference/tests/data/koch_edges.json: n1/n2 the
// point at a third of the edge from n0's vertex, n3 the apex). The true positions are computed
// here: thirds of the edge, and the apex at the edge midpoint plus sqrt(3)/6 times the edge
// rotated outwards (equilateral bump). Inferred from the square, the apex is an affine
// combination of the points of interest, (1 + k) p_e - k p_f with k ~ sqrt(3)/3: along the vector
// face barycentre -> edge midpoint, which is the edge normal with the right length on the square
// only. Applied to the first iteration (a 16-gon), it misplaces the apexes while the thirds stay
// right; and inferred from the pair (iteration 1, iteration 2) the apex has no solution at all
// (nor, through rounding, the thirds: see the second test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "inference/expression_inference.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"

// A named namespace: the tests are built as one unity source.
namespace koch_positions {

using namespace gmr;
using namespace gmr::inference;
using Status = InferredExpression::Status;

std::string source(const std::string& rel) {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/" + rel;
}

scheme::RuleScheme koch() {
  return io::read_scheme_file(source("inference/tests/data/koch_edges.json"));
}

Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 operator*(double k, const Vec3& a) { return {k * a[0], k * a[1], k * a[2]}; }

// Per dart of a flat (z = 0) map: its edge rotated by 90 degrees away from the polygon of its face
// (the face walked along alpha0 alpha1, oriented by its signed area).
std::vector<Vec3> outward_edges(const EmbeddedMap& m) {
  const auto& pos = m.find("position")->values;
  std::vector<Vec3> out(m.map.capacity(), Vec3{0, 0, 0});
  for (Dart rep : orbit_representatives(m.map, OrbitType{0, 1})) {
    std::vector<Dart> walk;
    double area = 0;
    Dart x = rep;
    do {
      walk.push_back(x);
      const Vec3 a = pos.get(x), b = pos.get(m.map.alpha(0, x));
      area += a[0] * b[1] - b[0] * a[1];
      x = m.map.alpha(1, m.map.alpha(0, x));
    } while (x != rep);
    for (Dart y : walk) {
      const Vec3 e = pos.get(m.map.alpha(0, y)) - pos.get(y);
      const Vec3 n = area > 0 ? Vec3{e[1], -e[0], 0} : Vec3{-e[1], e[0], 0};
      out[y] = n;
      out[m.map.alpha(0, y)] = n;
    }
  }
  return out;
}

// `m` with vertex positions pos(d) (one value per <1,2>-orbit).
template <class Pos>
EmbeddedMap with_positions(const Map& g, Pos pos) {
  EmbeddedMap m;
  m.map = g;
  m.fields.push_back(EmbeddingField::numeric("position", OrbitType{1, 2}));
  for (Dart r : orbit_representatives(g, OrbitType{1, 2})) m.fields[0].values.set(g, r, pos(r));
  return m;
}

// Which R node of the Koch scheme each dart of the result stands for (comatch).
std::vector<uint32_t> node_of(const scheme::SchemeApplication& app, size_t capacity, size_t nodes) {
  std::vector<uint32_t> v(capacity, 0);
  for (uint32_t n = 0; n < nodes; ++n)
    for (uint32_t b = 0; b < app.orbit_size(); ++b) v[app.comatch_at(n, b)] = n;
  return v;
}

// One true von Koch step on every edge of the flat map `m`.
EmbeddedMap koch_step(const EmbeddedMap& m) {
  const auto& pos = m.find("position")->values;
  const std::vector<Vec3> out = outward_edges(m);
  Map g = m.map;
  const scheme::SchemeApplication app = scheme::apply(scheme::SchemeEngine(koch()), g, {0});
  EXPECT_TRUE(app.applied) << app.why;
  std::vector<Vec3> p(g.capacity(), Vec3{0, 0, 0});
  for (uint32_t b = 0; b < app.orbit_size(); ++b) {
    const Dart x = app.match_at(0, b);
    const Vec3 a = pos.get(x), c = pos.get(m.map.alpha(0, x));
    p[app.comatch_at(0, b)] = a;
    p[app.comatch_at(1, b)] = a + (1.0 / 3.0) * (c - a);
    p[app.comatch_at(2, b)] = a + (1.0 / 3.0) * (c - a);
    p[app.comatch_at(3, b)] = 0.5 * (a + c) + (std::sqrt(3.0) / 6.0) * out[x];
  }
  return with_positions(g, [&](Dart d) { return p[d]; });
}

const InferredExpression& node(const ExpressionInference& inf, const std::string& name) {
  for (const auto& n : inf.nodes)
    if (n.node == name) return n;
  throw std::runtime_error("no node " + name);
}

void print(const ExpressionInference& inf) {
  for (const auto& n : inf.nodes)
    std::cout << "[ infer    ] " << n.node << ": "
              << (n.status == Status::Solved ? n.code + (n.unique ? "  [unique]" : "  [not unique]")
                  : n.status == Status::Kept ? "[kept]"
                  : n.status == Status::Inherited ? "[inherited (solved class)]"
                                                  : "[no solution]")
              << "\n";
}

EmbeddedMap square() { return io::read_off_file(source("inference/tests/data/square_pillow.off")); }

TEST(ExpressionInference, VonKochFromTheSquareReproducesTheFirstIteration) {
  const EmbeddedMap sq = square();
  const EmbeddedMap sq1 = koch_step(sq);
  const ExpressionInference inf = infer_expressions(koch(), sq, {0}, sq1);
  print(inf);
  EXPECT_EQ(node(inf, "n0").status, Status::Kept);
  EXPECT_EQ(node(inf, "n1").status, Status::Solved);
  EXPECT_EQ(node(inf, "n1").code, "(1/3) * n0.position + (2/3) * middle(<0>_position(n0))");
  EXPECT_EQ(node(inf, "n2").status, Status::Inherited);
  ASSERT_EQ(node(inf, "n3").status, Status::Solved);
  // The apex along face barycentre -> edge midpoint: weights on p_e and p_f only.
  EXPECT_NE(node(inf, "n3").code.find("middle(<0>_position(n0))"), std::string::npos);
  EXPECT_NE(node(inf, "n3").code.find("middle(<0,1>_position(n0))"), std::string::npos);
  // Applied to the square, the inferred scheme gives the first iteration.
  EmbeddedMap again = sq;
  const expr::CompiledScheme cs = expr::compile_scheme(inf.scheme);
  expr::EmbeddingPropagation prop(cs, again);
  ASSERT_TRUE(scheme::apply(scheme::SchemeEngine(inf.scheme), again.map, {0}, &prop));
  const auto& a = again.fields[0].values;
  const auto& b = sq1.fields[0].values;
  for (Dart d = 0; d < again.map.capacity(); ++d)
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(a.get(d)[c], b.get(d)[c], 1e-9) << "dart " << d;
}

TEST(ExpressionInference, VonKochFailsFromTheSecondIteration) {
  const EmbeddedMap sq = square();
  const EmbeddedMap sq1 = koch_step(sq);
  const EmbeddedMap sq2 = koch_step(sq1);
  // (a) The expressions inferred from the square, applied to the first iteration: the thirds are
  // right, the apexes are not (the 16-gon's barycentre is not in the normal of its edges).
  const ExpressionInference from_square = infer_expressions(koch(), sq, {0}, sq1);
  EmbeddedMap got = sq1;
  const expr::CompiledScheme cs = expr::compile_scheme(from_square.scheme);
  expr::EmbeddingPropagation prop(cs, got);
  const scheme::SchemeApplication app =
      scheme::apply(scheme::SchemeEngine(from_square.scheme), got.map, {0}, &prop);
  ASSERT_TRUE(app.applied) << app.why;
  EXPECT_EQ(prop.issue_count(), 0u);
  const std::vector<uint32_t> nd = node_of(app, got.map.capacity(), 4);
  double thirds_error = 0, apex_error = 0;
  for (Dart d = 0; d < got.map.capacity(); ++d) {
    const Vec3 e = got.fields[0].values.get(d) - sq2.fields[0].values.get(d);
    const double err = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    if (nd[d] == 3)
      apex_error = std::max(apex_error, err);
    else
      thirds_error = std::max(thirds_error, err);
  }
  std::cout << "[ koch     ] second iteration with the expressions inferred from the square: "
               "largest error "
            << thirds_error << " at kept vertices and thirds, " << apex_error << " at apexes\n";
  EXPECT_LT(thirds_error, 1e-9);
  EXPECT_GT(apex_error, 0.01);
  // (b) Inferred from the pair (first iteration, second iteration): no solution is reported for
  // the apexes, which no affine expression of the points of interest gives (a). The thirds, right
  // in (a) to 2e-16, get no solution either: their coordinates involve sqrt(3), and the exact
  // solver reads each double as the simplest rational within 1e-9 (expression_inference.hpp), so
  // the exact system of the rounded values is inconsistent. A limit of exact solving on
  // irrational data, where the thesis' floating-point solver has a tolerance.
  const ExpressionInference from_first = infer_expressions(koch(), sq1, {0}, sq2);
  print(from_first);
  EXPECT_EQ(node(from_first, "n0").status, Status::Kept);
  EXPECT_EQ(node(from_first, "n1").status, Status::NoSolution);
  EXPECT_EQ(node(from_first, "n3").status, Status::NoSolution);
}

}  // namespace koch_positions
