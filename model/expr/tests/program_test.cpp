// Compiled programs (program.hpp) against the tree interpreter, their oracle: the same value, bit
// for bit, and the same error message at every dart of random surfaces, plain and in memo mode,
// for the expressions of the four library subdivision schemes and for random expressions;
// constant folding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/evaluator.hpp"
#include "model/expr/parser.hpp"
#include "model/expr/program.hpp"
#include "model/expr/type_check.hpp"
#include "model/io/scheme_json.hpp"
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

struct Surface {
  Map g{2};
  EmbeddingField pos{3, Embedding<Vec3>("position", OrbitType{1, 2})};
  EmbeddingField weight{1, Embedding<Vec3>("weight", OrbitType{0, 1})};
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
  auto coordinate = [&] { return static_cast<double>(gt::uniform(rng, 0, 1 << 20)) / 4096.0 - 128.0; };
  for (Dart r : orbit_representatives(s.g, OrbitType{1, 2})) s.pos.values.set(s.g, r, {coordinate(), coordinate(), coordinate()});
  for (Dart r : orbit_representatives(s.g, OrbitType{0, 1}))
    if (!gt::chance(rng, 5)) s.weight.values.set(s.g, r, {static_cast<double>(gt::uniform(rng, 0, 8)), 0, 0});
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
        const std::string where = what + ", seed " + std::to_string(seed) + (memo ? ", memo" : "") + ", dart " +
                                  std::to_string(d);
        EXPECT_EQ(a.error, b.error) << where;
        if (!a.error.empty() || !b.error.empty()) {
          ++compared;
          continue;
        }
        const double xa[4] = {a.v.x, a.v.y, a.v.z, a.v.w}, xb[4] = {b.v.x, b.v.y, b.v.z, b.v.w};
        for (int k = 0; k < 4; ++k)
          EXPECT_TRUE(bitwise(xa[k], xb[k])) << where << ": " << xa[k] << " vs " << xb[k];
        ++compared;
        if (::testing::Test::HasFailure()) return compared;
      }
    }
  }
  return compared;
}

TEST(ExpressionProgram, SubdivisionSchemesMasksGiveTheTreesValues) {
  size_t expressions = 0, compared = 0;
  for (const char* file : {"quad_subdivision.json", "loop_subdivision.json", "sqrt3_subdivision.json",
                           "doo_sabin_subdivision.json"}) {
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
    const unsigned k = static_cast<unsigned>(gt::uniform(rng_, 0, depth <= 0 ? 1 : 7));
    switch (k) {
      case 0: return ref() + ".position";
      case 1: return "middle(" + orbit() + "_position(" + ref() + "))";
      case 2: return "(" + point(depth - 1) + " + " + point(depth - 1) + ") / 2";
      case 3: return "(1 - " + unit(depth - 1) + ") * " + point(depth - 1) + " + " + unit(depth - 1) + " * " + point(depth - 1);
      case 4: {
        const std::string x = fresh();
        scope_.push_back(x);
        const std::string body = point(depth - 1);
        scope_.pop_back();
        return "middle([" + body + " | " + x + " in " + orbit() + "/" + orbit() + "(" + ref() + ")])";
      }
      case 5: return point(depth - 1) + " + (" + point(depth - 1) + " - " + point(depth - 1) + ")";
      case 6: {
        const std::string x = fresh(), i = fresh();
        scope_.push_back(x);
        const std::string body = point(depth - 1);
        scope_.pop_back();
        return "middle([" + body + " | " + x + ", " + i + " in (@0@1)*(" + ref() + ")])";
      }
      default: return "middle(" + point(depth - 1) + ", " + point(depth - 1) + ", " + point(depth - 1) + ")";
    }
  }
  std::string scalar(int depth) {
    const unsigned k = static_cast<unsigned>(gt::uniform(rng_, 0, depth <= 0 ? 2 : 11));
    switch (k) {
      case 0: return std::to_string(gt::uniform(rng_, 0, 9));
      case 1: return ref() + ".weight";
      case 2: return "pi";
      case 3: return "count(" + orbit() + "_position(" + ref() + "))";
      case 4: return "count([0 | e in " + orbit() + "/" + orbit() + "(" + ref() + ")])";
      case 5: return "(" + scalar(depth - 1) + " + " + scalar(depth - 1) + ")";
      case 6: return "(" + scalar(depth - 1) + " / " + scalar(depth - 1) + ")";
      case 7: return "cos(" + scalar(depth - 1) + ")";
      case 8: return "norm(" + point(depth - 1) + " - " + point(depth - 1) + ")";
      case 9: return "sum(" + orbit() + "_weight(" + ref() + "))";
      case 10: {
        const std::string x = fresh();
        const std::string value = scalar(depth - 1);
        lets_.push_back(x);
        const std::string body = scalar(depth - 1);
        lets_.pop_back();
        return "(let " + x + " = " + value + " in " + body + " * " + x + ")";
      }
      default: return "sqrt(" + scalar(depth - 1) + " - 2)";
    }
  }

 private:
  // A scalar in [0, 1] when the weights are (abs and cos keep most of them there).
  std::string unit(int depth) { return "abs(cos(" + scalar(depth) + "))"; }
  std::string orbit() {
    static const char* kOrbits[] = {"<>", "<0>", "<1>", "<2>", "<0,1>", "<0,2>", "<1,2>", "<0,1,2>"};
    return kOrbits[gt::uniform(rng_, 0, 7)];
  }
  std::string ref() {
    std::string r = scope_.empty() || gt::chance(rng_, 40) ? "n0" : scope_[gt::uniform(rng_, 0, scope_.size() - 1)];
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
  size_t expressions = 0, compared = 0;
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
    compared += compare_everywhere(*e, t, code);
    if (HasFailure()) return;
  }
  EXPECT_GE(expressions, 40u);
  EXPECT_GT(compared, 50000u);
}

TEST(ExpressionProgram, ConstantsAreFoldedExceptWhatTheRunRejects) {
  const CheckContext ctx = context();
  auto compile = [&](const std::string& code, ValueType t) {
    auto e = parse_expression(code);
    check_expression(*e, ctx, t);
    std::optional<Program> p = compile_program(*e);
    EXPECT_TRUE(p.has_value()) << code;
    return std::make_pair(std::shared_ptr<Expr>(std::move(e)), *p);
  };
  {
    const auto [e, p] = compile("5/8 - (3 + 2 * cos(2 * pi / 6)) * (3 + 2 * cos(2 * pi / 6)) / 64", ValueType::Scalar);
    ASSERT_EQ(p.code.size(), 1u);
    EXPECT_EQ(p.code[0].op, Instruction::Op::Constant);
    const double c = 5.0 / 8 - (3 + 2 * std::cos(2 * M_PI / 6)) * (3 + 2 * std::cos(2 * M_PI / 6)) * (1.0 / 64);
    EXPECT_DOUBLE_EQ(p.code[0].value[0], c);
    EXPECT_NEAR(p.code[0].value[0], 3.0 / 8, 1e-15);  // Loop's weight at valence 6
  }
  {
    // Only the constant part of the edge mask folds: 3 (the weight) and 8; the values stay.
    const auto [e, p] = compile("(3 * (n0.position + n0@0.position) + n0@1@0.position + n0@2@1@0.position) / 8",
                                ValueType::Point);
    EXPECT_EQ(std::count_if(p.code.begin(), p.code.end(), [](const Instruction& i) { return i.op == Instruction::Op::Value; }), 4);
    EXPECT_EQ(p.code.size(), 11u);
  }
  const Surface s = random_surface(1);
  Evaluator ev(s.g, kSigs, {&s.pos, &s.weight});
  const Dart d = 0;
  for (const char* code : {"1 / (2 - 2)", "sqrt(1 - 2)"}) {
    const auto [e, p] = compile(code, ValueType::Scalar);
    EXPECT_GT(p.code.size(), 1u) << code;  // not folded: the run reports it
    const Outcome a = outcome(ev, *e, d, ValueType::Scalar), b = outcome(ev, p, d, ValueType::Scalar);
    EXPECT_FALSE(a.error.empty()) << code;
    EXPECT_EQ(a.error, b.error) << code;
  }
}

}  // namespace program_test
