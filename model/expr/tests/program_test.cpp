// Compiled programs (program.hpp) against the tree interpreter, their oracle: the same value (bit
// for bit; within 1e-12 relative when an affine combination is fused, its weights distributed) and
// the same error message at every dart of random surfaces, plain and in memo mode, for the
// expressions of the four library subdivision schemes and for random expressions; constant
// folding; fused combinations.
#include "model/expr/program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/evaluator.hpp"
#include "model/expr/parser.hpp"
#include "model/expr/type_check.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_maps.hpp"

using namespace gmr;
using namespace gmr::expr;
namespace gt = gmr::testing;

namespace program_test {

std::string rules_dir() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/tools/data/rules/";
}

const std::vector<EmbeddingSignature> kSigs{{"position", OrbitType{1, 2}, ValueType::Point},
                                            {"weight", OrbitType{0, 1}, ValueType::Scalar}};

CheckContext context() {
  CheckContext ctx;
  ctx.nodes = {"n0"};
  ctx.embeddings = kSigs;
  return ctx;
}

// An expression of type t parsed, checked and compiled (the program must exist).
std::pair<std::shared_ptr<Expr>, Program> compile(const std::string& code, ValueType t) {
  auto e = parse_expression(code);
  check_expression(*e, context(), t);
  std::optional<Program> p = compile_program(*e);
  EXPECT_TRUE(p.has_value()) << code;
  return std::make_pair(std::shared_ptr<Expr>(std::move(e)), *p);
}

struct Surface {
  Map g{2};
  EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
  EmbeddingField weight = EmbeddingField::numeric("weight", OrbitType{0, 1}, 1);
};

// A random surface (1-gons and 2-gons on even seeds: faces through one vertex twice), positions on
// every vertex, weights on most faces (a missing weight is a run-time error to reproduce).
Surface random_surface(uint64_t seed) {
  gt::Rng rng(500 + seed);
  gt::GluedPolygonsOptions opt;
  opt.min_sides = seed % 2 == 0 ? 1 : 3;
  opt.max_extra_sews = 16;
  opt.connected = seed % 3 != 0;
  Surface s;
  s.g = gt::random_glued_polygons(rng, opt);
  auto coordinate = [&] {
    return static_cast<double>(gt::uniform(rng, 0, 1 << 20)) / 4096.0 - 128.0;
  };
  for (Dart r : orbit_representatives(s.g, OrbitType{1, 2}))
    s.pos.values.set(s.g, r, {coordinate(), coordinate(), coordinate()});
  for (Dart r : orbit_representatives(s.g, OrbitType{0, 1}))
    if (!gt::chance(rng, 5))
      s.weight.values.set(s.g, r, {static_cast<double>(gt::uniform(rng, 0, 8)), 0, 0});
  return s;
}

struct Outcome {
  Val v;
  std::string error;  // empty: no error
};

template <class E>
Outcome outcome(Evaluator& ev, const E& e, Dart d, ValueType t) {
  Outcome o;
  try {
    o.v = ev.evaluate(e, &d, t, "test");
  } catch (const Error& x) {
    o.error = x.what();
    if (o.error.empty()) o.error = "error";
  }
  return o;
}

bool bitwise(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
// A fused combination's value: the tree's up to rounding.
bool close(double a, double b) {
  return std::fabs(a - b) <= 1e-12 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// Compares the program of `e` with the tree at every dart of 20 random surfaces, in both modes;
// returns the number of values compared (errors included).
size_t compare_everywhere(const Expr& e, ValueType t, const std::string& what) {
  const std::optional<Program> p = compile_program(e);
  EXPECT_TRUE(p.has_value()) << what;
  if (!p) return 0;
  size_t compared = 0;
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const Surface s = random_surface(seed);
    for (const bool memo : {false, true}) {
      Evaluator tree(s.g, kSigs, {&s.pos, &s.weight});
      Evaluator flat(s.g, kSigs, {&s.pos, &s.weight});
      tree.memoise_collects(memo);
      flat.memoise_collects(memo);
      for (Dart d : s.g.darts()) {
        const Outcome a = outcome(tree, e, d, t);
        const Outcome b = outcome(flat, *p, d, t);
        const std::string where = what + ", seed " + std::to_string(seed) + (memo ? ", memo" : "") +
                                  ", dart " + std::to_string(d);
        EXPECT_EQ(a.error, b.error) << where;
        if (!a.error.empty() || !b.error.empty()) {
          ++compared;
          continue;
        }
        const double xa[4] = {a.v.x, a.v.y, a.v.z, a.v.w}, xb[4] = {b.v.x, b.v.y, b.v.z, b.v.w};
        for (int k = 0; k < 4; ++k)
          EXPECT_TRUE(p->fused ? close(xa[k], xb[k]) : bitwise(xa[k], xb[k]))
              << where << ": " << xa[k] << " vs " << xb[k];
        ++compared;
        if (::testing::Test::HasFailure()) return compared;
      }
    }
  }
  return compared;
}

TEST(ExpressionProgram, SubdivisionSchemesMasksGiveTheTreesValues) {
  size_t expressions = 0, compared = 0;
  for (const char* file : {"quad_subdivision.json", "loop_subdivision.json",
                           "sqrt3_subdivision.json", "doo_sabin_subdivision.json"}) {
    const scheme::RuleScheme s = io::read_scheme_file(rules_dir() + file);
    const CompiledScheme cs = compile_scheme(s);
    for (size_t k = 0; k < cs.embeddings.size(); ++k)
      for (size_t v = 0; v < cs.right[k].size(); ++v) {
        if (!cs.right[k][v]) continue;
        ++expressions;
        compared += compare_everywhere(*cs.right[k][v], cs.embeddings[k].type,
                                       std::string(file) + ", R node " + s.right.nodes[v].name);
      }
  }
  EXPECT_EQ(expressions, 8u);  // 3 Catmull-Clark, 2 Loop, 2 sqrt(3), 1 Doo-Sabin
  EXPECT_GT(compared, 10000u);
}

// Random well-typed expressions: scalars and points over collects, comprehensions (nested, with
// paths from their variable), walks, lets, divisions (by zero at some darts) and functions.
class RandomExpression {
 public:
  explicit RandomExpression(gt::Rng& rng) : rng_(rng) {}
  std::string point(int depth) {
    const unsigned k = static_cast<unsigned>(gt::uniform(rng_, 0, depth <= 0 ? 1 : 8));
    switch (k) {
      case 0:
        return ref() + ".position";
      case 1:
        return "middle(" + orbit() + "_position(" + ref() + "))";
      case 2:
        return "(" + point(depth - 1) + " + " + point(depth - 1) + ") / 2";
      case 3:
        return "(1 - " + unit(depth - 1) + ") * " + point(depth - 1) + " + " + unit(depth - 1) +
               " * " + point(depth - 1);
      case 4: {
        const std::string x = fresh();
        scope_.push_back(x);
        const std::string body = point(depth - 1);
        scope_.pop_back();
        return "middle([" + body + " | " + x + " in " + orbit() + "/" + orbit() + "(" + ref() +
               ")])";
      }
      case 5:
        return point(depth - 1) + " + (" + point(depth - 1) + " - " + point(depth - 1) + ")";
      case 6: {
        const std::string x = fresh(), i = fresh();
        scope_.push_back(x);
        const std::string body = point(depth - 1);
        scope_.pop_back();
        return "middle([" + body + " | " + x + ", " + i + " in (@0@1)*(" + ref() + ")])";
      }
      case 7:  // an affine combination of node values with constant weights (fused)
        return "(3 * " + ref() + ".position + " + point(depth - 1) + " - (" + ref() +
               ".position - " + ref() + ".position)) / 4";
      default:
        return "middle(" + point(depth - 1) + ", " + point(depth - 1) + ", " + point(depth - 1) +
               ")";
    }
  }
  std::string scalar(int depth) {
    const unsigned k = static_cast<unsigned>(gt::uniform(rng_, 0, depth <= 0 ? 2 : 12));
    switch (k) {
      case 0:
        return std::to_string(gt::uniform(rng_, 0, 9));
      case 1:
        return ref() + ".weight";
      case 2:
        return "pi";
      case 3:
        return "count(" + orbit() + "_position(" + ref() + "))";
      case 4:
        return "count([0 | e in " + orbit() + "/" + orbit() + "(" + ref() + ")])";
      case 5:
        return "(" + scalar(depth - 1) + " + " + scalar(depth - 1) + ")";
      case 6:
        return "(" + scalar(depth - 1) + " / " + scalar(depth - 1) + ")";
      case 7:
        return "cos(" + scalar(depth - 1) + ")";
      case 8:
        return "norm(" + point(depth - 1) + " - " + point(depth - 1) + ")";
      case 9:
        return "sum(" + orbit() + "_weight(" + ref() + "))";
      case 10: {
        const std::string x = fresh();
        const std::string value = scalar(depth - 1);
        lets_.push_back(x);
        const std::string body = scalar(depth - 1);
        lets_.pop_back();
        return "(let " + x + " = " + value + " in " + body + " * " + x + ")";
      }
      case 11:  // fused, node weights possibly missing (the error of the first met)
        return "(" + ref() + ".weight - 2 * " + ref() + ".weight + " + scalar(depth - 1) +
               " / 3 + 1)";
      default:
        return "sqrt(" + scalar(depth - 1) + " - 2)";
    }
  }

 private:
  // A scalar in [0, 1] when the weights are (abs and cos keep most of them there).
  std::string unit(int depth) { return "abs(cos(" + scalar(depth) + "))"; }
  std::string orbit() {
    static const char* kOrbits[] = {"<>",    "<0>",   "<1>",   "<2>",
                                    "<0,1>", "<0,2>", "<1,2>", "<0,1,2>"};
    return kOrbits[gt::uniform(rng_, 0, 7)];
  }
  std::string ref() {
    std::string r = scope_.empty() || gt::chance(rng_, 40)
                        ? "n0"
                        : scope_[gt::uniform(rng_, 0, scope_.size() - 1)];
    const uint64_t steps = gt::uniform(rng_, 0, 2);
    for (uint64_t k = 0; k < steps; ++k) r += "@" + std::to_string(gt::uniform(rng_, 0, 2));
    return r;
  }
  std::string fresh() { return "v" + std::to_string(next_++); }
  gt::Rng& rng_;
  std::vector<std::string> scope_, lets_;
  int next_ = 0;
};

TEST(ExpressionProgram, RandomExpressionsGiveTheTreesValuesAndErrors) {
  const CheckContext ctx = context();
  size_t expressions = 0, compared = 0, fused = 0;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    gt::Rng rng(42000 + seed);
    RandomExpression gen(rng);
    const bool is_point = seed % 2 == 0;
    const std::string code = is_point ? gen.point(3) : gen.scalar(3);
    auto e = parse_expression(code);
    const ValueType t = is_point ? ValueType::Point : ValueType::Scalar;
    try {
      check_expression(*e, ctx, t);
    } catch (const Error&) {
      continue;  // e.g. a mass known only at run time is fine; an ill-typed draw is skipped
    }
    ++expressions;
    if (const std::optional<Program> p = compile_program(*e); p && p->fused) ++fused;
    compared += compare_everywhere(*e, t, code);
    if (HasFailure()) return;
  }
  EXPECT_GE(expressions, 40u);
  EXPECT_GE(fused, 10u);  // fused combinations (within 1e-12) are among them
  EXPECT_GT(compared, 50000u);
}

TEST(ExpressionProgram, ConstantsAreFoldedExceptWhatTheRunRejects) {
  {
    const auto [e, p] = compile("5/8 - (3 + 2 * cos(2 * pi / 6)) * (3 + 2 * cos(2 * pi / 6)) / 64",
                                ValueType::Scalar);
    ASSERT_EQ(p.code.size(), 1u);
    EXPECT_EQ(p.code[0].op, Instruction::Op::Constant);
    const double c =
        5.0 / 8 - (3 + 2 * std::cos(2 * M_PI / 6)) * (3 + 2 * std::cos(2 * M_PI / 6)) * (1.0 / 64);
    EXPECT_DOUBLE_EQ(p.code[0].value[0], c);
    EXPECT_NEAR(p.code[0].value[0], 3.0 / 8, 1e-15);  // Loop's weight at valence 6
  }
  const Surface s = random_surface(1);
  Evaluator ev(s.g, kSigs, {&s.pos, &s.weight});
  const Dart d = 0;
  for (const char* code : {"1 / (2 - 2)", "sqrt(1 - 2)"}) {
    const auto [e, p] = compile(code, ValueType::Scalar);
    EXPECT_GT(p.code.size(), 1u) << code;  // not folded: the run reports it
    const Outcome a = outcome(ev, *e, d, ValueType::Scalar),
                  b = outcome(ev, p, d, ValueType::Scalar);
    EXPECT_FALSE(a.error.empty()) << code;
    EXPECT_EQ(a.error, b.error) << code;
  }
}

// Affine combinations with constant weights are one fused instruction per run of node values; the
// other operands keep their programs and are accumulated with their weights, in the tree's order.
TEST(ExpressionProgram, AffineCombinationsOfNodeValuesAreFused) {
  using Op = Instruction::Op;
  {
    // Loop's edge mask: one instruction, weights 3/8, 3/8, 1/8, 1/8 on the four node values.
    const auto [e, p] =
        compile("(3 * (n0.position + n0@0.position) + n0@1@0.position + n0@2@1@0.position) / 8",
                ValueType::Point);
    ASSERT_EQ(p.code.size(), 1u);
    EXPECT_EQ(p.code[0].op, Op::Combine);
    EXPECT_TRUE(p.fused);
    ASSERT_EQ(p.code[0].count, 4u);
    ASSERT_EQ(p.loads.size(), 4u);
    const double w[4] = {3.0 / 8, 3.0 / 8, 1.0 / 8, 1.0 / 8};
    const std::vector<std::vector<uint8_t>> paths{{}, {0}, {1, 0}, {2, 1, 0}};
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(p.loads[k].weight, w[k]) << k;
      EXPECT_EQ(std::vector<uint8_t>(p.loads[k].path, p.loads[k].path + p.loads[k].length),
                paths[k])
          << k;
    }
    for (int x = 0; x < 4; ++x) EXPECT_EQ(p.code[0].value[x], 0.0);  // no constant term
  }
  {
    // Catmull-Clark's edge point: the two node values fused, each barycentre accumulated with 1/4.
    const auto [e, p] = compile(
        "(n0.position + n0@0.position + middle(<0,1>_position(n0)) + middle(<0,1>_position(n0@2))) "
        "/ 4",
        ValueType::Point);
    std::vector<Op> ops;
    for (const Instruction& i : p.code) ops.push_back(i.op);
    EXPECT_EQ(ops, (std::vector<Op>{Op::Combine, Op::AggregateSet, Op::Accumulate, Op::AggregateSet,
                                    Op::Accumulate}));
    EXPECT_EQ(p.code[2].value[0], 0.25);
    EXPECT_EQ(p.code[0].count, 2u);
  }
  {
    // Constants become the offset; subtraction and negation negate weights; a second run of node
    // values after another operand is added to the accumulator.
    const auto [e, p] =
        compile("n0.weight - 2 * n0@1.weight + count(<0>_position(n0)) - (-n0@0.weight) + 3",
                ValueType::Scalar);
    std::vector<Op> ops;
    for (const Instruction& i : p.code) ops.push_back(i.op);
    EXPECT_EQ(ops,
              (std::vector<Op>{Op::Combine, Op::AggregateSet, Op::Accumulate, Op::CombineLoads}));
    EXPECT_EQ(p.code[0].value[0], 3.0);
    ASSERT_EQ(p.loads.size(), 3u);
    EXPECT_EQ(p.loads[0].weight, 1.0);
    EXPECT_EQ(p.loads[1].weight, -2.0);
    EXPECT_EQ(p.loads[2].weight, 1.0);
    const Surface s = random_surface(3);
    Evaluator ev(s.g, kSigs, {&s.pos, &s.weight});
    size_t values = 0;
    for (Dart d : s.g.darts()) {
      const Outcome a = outcome(ev, *e, d, ValueType::Scalar),
                    b = outcome(ev, p, d, ValueType::Scalar);
      EXPECT_EQ(a.error, b.error) << d;
      if (a.error.empty()) {
        EXPECT_TRUE(close(a.v.x, b.v.x)) << d << ": " << a.v.x << " vs " << b.v.x;
        ++values;
      }
    }
    EXPECT_GT(values, 0u);
  }
  {
    // One node value per combination: nothing to fuse. A division by a run-time scalar: only its
    // dividend is fused.
    const std::pair<const char*, long> cases[] = {
        {"(1 - n0.weight) * n0.position + n0.weight * middle(<0>_position(n0))", 0},
        {"(n0.position + n0@0.position) / n0.weight", 1}};
    for (const auto& [code, combines] : cases) {
      const auto [e, p] = compile(code, ValueType::Point);
      (void)e;
      EXPECT_EQ(std::count_if(p.code.begin(), p.code.end(),
                              [](const Instruction& i) { return i.op == Op::Combine; }),
                combines)
          << code;
      EXPECT_EQ(p.code.back().op, combines ? Op::Div : Op::Add) << code;
    }
  }
  {
    // A path longer than a load holds stays a generic value.
    const auto [e, p] = compile("n0@0@1@0@1@0@1@0.position", ValueType::Point);
    ASSERT_EQ(p.code.size(), 1u);
    EXPECT_EQ(p.code[0].op, Op::Value);
  }
}

// A dart-free sub-expression of let variables is enclosed in Pure ... PureEnd; the evaluator gives
// its last result again for equal let values, bit for bit the tree's, and keeps nothing from a run
// that fails.
TEST(ExpressionProgram, DartFreeSubExpressionsKeepTheirLastResult) {
  const CheckContext ctx = context();
  using Op = Instruction::Op;
  auto pures = [](const Program& p) {
    return std::count_if(p.code.begin(), p.code.end(),
                         [](const Instruction& i) { return i.op == Op::Pure; });
  };
  {
    // Loop's vertex point: the weight c of the valence k is one kept sub-expression; (1 - c) is too
    // short to pay.
    const scheme::RuleScheme s = io::read_scheme_file(rules_dir() + "loop_subdivision.json");
    const CompiledScheme cs = compile_scheme(s);
    const std::optional<Program> p = compile_program(*cs.right[0][0]);
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(pures(*p), 1);
    const auto at = std::find_if(p->code.begin(), p->code.end(),
                                 [](const Instruction& i) { return i.op == Op::Pure; });
    EXPECT_GE(at->index, 15u);
    EXPECT_EQ((at + at->index + 1)->op, Op::PureEnd);
  }
  // 1 / (k - 4) fails on quads, at every dart of one (nothing kept), and not elsewhere.
  const std::string code = "let k = count(<0,1>_position(n0)) in 1 / (k - 4) + cos(2 * pi / k)";
  auto e = parse_expression(code);
  check_expression(*e, ctx, ValueType::Scalar);
  const std::optional<Program> p = compile_program(*e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(pures(*p), 1);
  EXPECT_GT(compare_everywhere(*e, ValueType::Scalar, code), 1000u);
  size_t errors = 0, values = 0;
  for (uint64_t seed = 1; seed < 8; seed += 2) {
    const Surface s = random_surface(seed);
    Evaluator tree(s.g, kSigs, {&s.pos, &s.weight});
    Evaluator flat(s.g, kSigs, {&s.pos, &s.weight});
    for (Dart d : s.g.darts())
      for (int twice = 0; twice < 2; ++twice) {
        const Outcome a = outcome(tree, *e, d, ValueType::Scalar),
                      b = outcome(flat, *p, d, ValueType::Scalar);
        EXPECT_EQ(a.error, b.error) << d;
        EXPECT_TRUE(bitwise(a.v.x, b.v.x)) << d;
        ++(a.error.empty() ? values : errors);
      }
  }
  EXPECT_GT(errors, 0u);
  EXPECT_GT(values, 0u);
}

// The last kKeptEntries results of a dart-free sub-expression are kept: over a surface whose faces
// have a few sizes, met in any order, the weight of a face size is computed once per size.
TEST(ExpressionProgram, DartFreeSubExpressionsKeepOneResultPerFewLetValues) {
  const CheckContext ctx = context();
  const std::string code =
      "let k = count(<0,1>_position(n0)) in cos(2 * pi / k) * (3 + 2 * cos(2 * pi / k))";
  auto e = parse_expression(code);
  check_expression(*e, ctx, ValueType::Scalar);
  const std::optional<Program> p = compile_program(*e);
  ASSERT_TRUE(p.has_value());
  size_t tested = 0;
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const Surface s = random_surface(seed);
    std::vector<Dart> vertex(s.g.capacity());
    for (Dart v : orbit_representatives(s.g, OrbitType{1, 2}))
      for (Dart x : orbit(s.g, OrbitType{1, 2}, v)) vertex[x] = v;
    std::set<size_t> sizes;  // the numbers of vertices of the faces (the count's values)
    for (Dart r : orbit_representatives(s.g, OrbitType{0, 1})) {
      std::set<Dart> met;
      for (Dart x : orbit(s.g, OrbitType{0, 1}, r)) met.insert(vertex[x]);
      sizes.insert(met.size());
    }
    if (sizes.size() < 2 || sizes.size() > 8) continue;  // one size, or more than are kept
    ++tested;
    Evaluator flat(s.g, kSigs, {&s.pos, &s.weight});
    for (int twice = 0; twice < 2; ++twice)
      for (Dart d : s.g.darts()) (void)flat.evaluate(*p, &d, ValueType::Scalar, "test");
    EXPECT_EQ(flat.pure_runs(), sizes.size()) << seed;
  }
  EXPECT_GE(tested, 5u);
}

// Evaluator::combine_classes: a program of one Combine instruction evaluated for all darts of a
// surface in one call gives run's values bit for bit; a dart whose load finds no value stops it
// there (the weights of some faces are missing), and evaluate() reports that dart's error.
TEST(ExpressionProgram, CombinationsOfManyClassesGiveRunsValuesAndStopAtTheFirstError) {
  size_t compared = 0, stopped = 0;
  for (const auto& [code, t] : std::vector<std::pair<std::string, ValueType>>{
           {"(3 * (n0.position + n0@0.position) + n0@1@0.position + n0@2@1@0.position) / 8",
            ValueType::Point},
           {"n0@1.position - n0@0@1.position", ValueType::Vector},
           {"2 * n0.weight - n0@2.weight / 4 + 1", ValueType::Scalar}}) {
    const auto [e, p] = compile(code, t);
    ASSERT_TRUE(Evaluator::combines_node_values(p)) << code;
    for (uint64_t seed = 0; seed < 20; ++seed) {
      const Surface s = random_surface(seed);
      Evaluator one(s.g, kSigs, {&s.pos, &s.weight}), many(s.g, kSigs, {&s.pos, &s.weight});
      one.memoise_collects(true);
      many.memoise_collects(true);
      const std::vector<Dart> darts = s.g.darts();
      std::vector<Vec3> out;
      const size_t done = many.combine_classes(p, darts.data(), darts.size(), t, out);
      ASSERT_EQ(out.size(), done) << code;
      for (size_t j = 0; j < darts.size(); ++j) {
        const Outcome a = outcome(one, p, darts[j], t);
        const std::string where =
            code + ", seed " + std::to_string(seed) + ", dart " + std::to_string(darts[j]);
        if (j == done) {
          EXPECT_FALSE(a.error.empty()) << where << ": stopped without an error";
          ++stopped;
          break;
        }
        ASSERT_TRUE(a.error.empty()) << where << ": " << a.error;
        const Vec3 x = Evaluator::to_storage(a.v);
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(bitwise(x[k], out[j][k])) << where;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(stopped, 0u);  // some weights are missing
  // Not one combination of node values: left to the run.
  const auto [e, p] = compile(
      "n0.position + (n0@0.position - n0@1.position) * count(<0>_position(n0))", ValueType::Point);
  EXPECT_FALSE(Evaluator::combines_node_values(p));
}

// The <1,2>-orbits of a surface listed as the whole-component path lists a class's orbit
// (component_propagation.cpp): from its first dart along alpha_2, alpha_1, ... until the walk
// closes or ends free, then from alpha_1 of the first dart the same way. starts: the first darts.
struct VertexLists {
  std::vector<uint32_t> list, start, number;
  std::vector<Dart> starts;
};
VertexLists list_vertices(const Map& g) {
  VertexLists v;
  v.number.assign(g.capacity(), UINT32_MAX);
  for (Dart d : g.darts()) {
    if (v.number[d] != UINT32_MAX) continue;
    const auto id = static_cast<uint32_t>(v.starts.size());
    v.starts.push_back(d);
    v.start.push_back(static_cast<uint32_t>(v.list.size()));
    auto visit = [&](Dart x) {
      v.number[x] = id;
      v.list.push_back(x);
    };
    visit(d);
    bool closed = false;
    for (int side = 0; side < 2 && !closed; ++side) {
      Dart x = side == 0 ? d : g.alpha(1, d);
      if (side == 1) {
        if (x == d) break;
        visit(x);
      }
      for (int dim = 2;; dim = 3 - dim) {
        const Dart y = g.alpha(dim, x);
        if (y == x) break;
        if (y == d) {
          closed = true;
          break;
        }
        visit(y);
        x = y;
      }
    }
  }
  v.start.push_back(static_cast<uint32_t>(v.list.size()));
  return v;
}

// Evaluator::run_classes: any program without unresolved values, evaluated for many classes in
// lanes, gives run's values bit for bit — at every dart (members walked by the evaluator), and at
// the first darts of the vertices with their orbits listed (members from the lists) — and stops at
// the batch holding the first class whose evaluation fails.
TEST(ExpressionProgram, ClassesInLanesGiveRunsValuesAndStopAtTheBatchThatFails) {
  std::vector<std::pair<std::string, ValueType>> codes;
  for (const char* file : {"quad_subdivision.json", "loop_subdivision.json",
                           "sqrt3_subdivision.json", "doo_sabin_subdivision.json"}) {
    const scheme::RuleScheme s = io::read_scheme_file(rules_dir() + file);
    for (const auto& node : s.right.nodes)
      for (const auto& x : node.expressions) codes.emplace_back(x.code, ValueType::Point);
  }
  for (uint64_t seed = 0; seed < 40; ++seed) {
    gt::Rng rng(77000 + seed);
    RandomExpression gen(rng);
    codes.emplace_back(seed % 2 == 0 ? gen.point(3) : gen.scalar(3),
                       seed % 2 == 0 ? ValueType::Point : ValueType::Scalar);
  }
  size_t programs = 0, compared = 0, stopped = 0, listed = 0;
  for (const auto& [code, t] : codes) {
    auto e = parse_expression(code);
    try {
      check_expression(*e, context(), t);
    } catch (const Error&) {
      continue;  // an ill-typed draw
    }
    const std::optional<Program> p = compile_program(*e);
    if (!p || !Evaluator::runs_in_lanes(*p)) continue;
    ++programs;
    for (uint64_t seed = 0; seed < 12; ++seed) {
      const Surface s = random_surface(seed);
      const VertexLists v = list_vertices(s.g);
      for (const bool vertices : {false, true}) {
        Evaluator one(s.g, kSigs, {&s.pos, &s.weight}), many(s.g, kSigs, {&s.pos, &s.weight});
        for (Evaluator* ev : {&one, &many}) {
          ev->memoise_collects(true);
          if (vertices)
            ev->share_orbit_lists(DimMask(6), v.list.data(), v.start.data(), v.number.data());
        }
        const std::vector<Dart> darts = vertices ? v.starts : s.g.darts();
        std::vector<Vec3> out;
        const size_t done = many.run_classes(*p, darts.data(), darts.size(), t, out);
        ASSERT_EQ(out.size(), done) << code;
        const std::string where =
            code + ", seed " + std::to_string(seed) + (vertices ? ", vertices" : "");
        for (size_t j = 0; j < done; ++j) {
          const Outcome a = outcome(one, *p, darts[j], t);
          ASSERT_TRUE(a.error.empty()) << where << ", dart " << darts[j] << ": " << a.error;
          const Vec3 x = Evaluator::to_storage(a.v);
          for (int k = 0; k < 3; ++k)
            ASSERT_TRUE(bitwise(x[k], out[j][k])) << where << ", dart " << darts[j];
          ++compared;
          listed += vertices ? 1 : 0;
        }
        if (done < darts.size()) {
          bool failed = false;
          for (size_t j = done; j < std::min(darts.size(), done + 64) && !failed; ++j)
            failed = !outcome(one, *p, darts[j], t).error.empty();
          EXPECT_TRUE(failed) << where << ": stopped at " << done
                              << " without an error in its batch";
          ++stopped;
        }
      }
    }
  }
  EXPECT_GE(programs, 25u);
  EXPECT_GT(compared, 20000u);
  EXPECT_GT(listed, 2000u);
  EXPECT_GT(stopped, 0u);  // missing weights, divisions by zero, square roots of negatives
  // An unresolved node value (a path longer than a load holds) is left to the run.
  const auto [e, p] = compile("n0@0@1@0@1@0@1@0.position", ValueType::Point);
  EXPECT_FALSE(Evaluator::runs_in_lanes(p));
}

}  // namespace program_test
