// The evaluator's memo mode (memoise_collects: memoised collects, <c>-orbits told apart by orbit
// numbers) gives the values of the plain evaluation (orbits marked one by one), at every dart of
// random surfaces, for collects, comprehensions and the subdivision masks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "model/core/orbit.hpp"
#include "model/expr/evaluator.hpp"
#include "model/expr/parser.hpp"
#include "model/expr/program.hpp"
#include "model/expr/type_check.hpp"
#include "model/testing/random_maps.hpp"

using namespace gmr;
using namespace gmr::expr;
namespace gt = gmr::testing;

namespace {

struct MemoCase {
  const char* code;
  ValueType type;
};
const MemoCase kMemoExpressions[] = {
    {"middle(<0,1>_position(n0))", ValueType::Point},
    {"count(<0,1>_position(n0))", ValueType::Scalar},
    {"sum(<0,1,2>_position(n0@1)) - count(<0,1,2>_position(n0)) * n0.position", ValueType::Vector},
    {"count([0 | e in <1,2>/<0,2>(n0)])", ValueType::Scalar},
    {"count([0 | e in <0,1,2>/<1>(n0)])", ValueType::Scalar},
    {"middle([e@0.position | e in <1,2>/<0,2>(n0)])", ValueType::Point},
    {"middle([middle(<0,1>_position(f)) | f in <1,2>/<0,1>(n0)])", ValueType::Point},
    {"middle([middle([x@0.position | x in <0,1>/<1,2>(f)]) | f in <1,2>/<0,1>(n0)])",
     ValueType::Point},
    {"let n = count([0 | e in <1,2>/<0,2>(n0)]) in (middle([middle(<0,1>_position(f)) | f in "
     "<1,2>/<0,1>(n0)]) + "
     "2 * middle([middle(<0>_position(e)) | e in <1,2>/<0,2>(n0)]) + (n - 3) * n0.position) / n",
     ValueType::Point},
    {"(n0.position + n0@0.position + middle(<0,1>_position(n0)) + middle(<0,1>_position(n0@2))) / "
     "4",
     ValueType::Point},
};

bool memo_close(double a, double b) {
  return std::fabs(a - b) <= 1e-12 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// A random surface of the seed's kind: 1-gons and 2-gons on even seeds (faces through one vertex
// twice), disconnected on every third seed.
Map varied_surface(uint64_t seed, gt::Rng& rng) {
  gt::GluedPolygonsOptions opt;
  opt.min_sides = seed % 2 == 0 ? 1 : 3;
  opt.max_extra_sews = 16;
  opt.connected = seed % 3 != 0;
  return gt::random_glued_polygons(rng, opt);
}

TEST(EvaluatorMemo, MemoModeGivesThePlainValuesEverywhere) {
  const std::vector<EmbeddingSignature> sigs{{"position", OrbitType{1, 2}, ValueType::Point}};
  CheckContext ctx;
  ctx.nodes = {"n0"};
  ctx.embeddings = sigs;
  size_t compared = 0;
  for (uint64_t seed = 0; seed < 30; ++seed) {
    gt::Rng rng(300 + seed);
    const Map g = varied_surface(seed, rng);
    EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
    for (Dart r : orbit_representatives(g, OrbitType{1, 2}))
      pos.values.set(g, r,
                     {static_cast<double>(gt::uniform(rng, 0, 1000)),
                      static_cast<double>(gt::uniform(rng, 0, 1000)),
                      static_cast<double>(gt::uniform(rng, 0, 1000))});
    for (const auto& [code, t] : kMemoExpressions) {
      auto e = parse_expression(code);
      check_expression(*e, ctx, t);
      Evaluator plain(g, sigs, {&pos});
      Evaluator memo(g, sigs, {&pos});
      memo.memoise_collects(true);
      for (Dart d : g.darts()) {
        Val a, b;
        bool fa = false, fb = false;
        try {
          a = plain.evaluate(*e, &d, t, "test");
        } catch (const Error&) {
          fa = true;
        }
        try {
          b = memo.evaluate(*e, &d, t, "test");
        } catch (const Error&) {
          fb = true;
        }
        ASSERT_EQ(fa, fb) << code << ", seed " << seed << ", dart " << d;
        if (fa) continue;
        ASSERT_TRUE(memo_close(a.x, b.x) && memo_close(a.y, b.y) && memo_close(a.z, b.z) &&
                    memo_close(a.w, b.w))
            << code << ", seed " << seed << ", dart " << d << ": " << a.x << " vs " << b.x;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000u);
}

// Memo mode lists the darts of an <a,b>-orbit without a marker (cycles and paths: the surfaces
// have boundaries); the order must be the marked walk's, since it decides the first dart met of
// each <c>-orbit (x@k.position below depends on it) and the order of the floating-point sum
// (positions that are not dyadic): memo and plain values are equal bit for bit.
TEST(EvaluatorMemo, TwoDimensionOrbitsAreListedInTheMarkedWalksOrder) {
  const std::vector<EmbeddingSignature> sigs{{"position", OrbitType{1, 2}, ValueType::Point}};
  CheckContext ctx;
  ctx.nodes = {"n0"};
  ctx.embeddings = sigs;
  const char* codes[] = {
      "middle([x@0.position | x in <1,2>/<2>(n0)])", "middle([x@1.position | x in <0,1>/<0>(n0)])",
      "middle([x@1.position | x in <0,2>/<>(n0)])", "middle([x@2@0.position | x in <1,2>/<>(n0)])",
      "middle([x@0@1.position | x in <0,2>/<2>(n0)])"};
  size_t compared = 0, paths = 0;
  for (uint64_t seed = 0; seed < 30; ++seed) {
    gt::Rng rng(700 + seed);
    const Map g = varied_surface(seed, rng);
    for (Dart d : g.darts()) paths += g.is_free(2, d) ? 1 : 0;
    EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
    for (Dart r : orbit_representatives(g, OrbitType{1, 2}))
      pos.values.set(g, r,
                     {static_cast<double>(gt::uniform(rng, 0, 1000)) / 7.0,
                      static_cast<double>(gt::uniform(rng, 0, 1000)) / 3.0,
                      static_cast<double>(gt::uniform(rng, 0, 1000)) / 11.0});
    for (const char* code : codes) {
      auto e = parse_expression(code);
      check_expression(*e, ctx, ValueType::Point);
      Evaluator plain(g, sigs, {&pos});
      Evaluator memo(g, sigs, {&pos});
      memo.memoise_collects(true);
      for (Dart d : g.darts()) {
        const Val a = plain.evaluate(*e, &d, ValueType::Point, "test");
        const Val b = memo.evaluate(*e, &d, ValueType::Point, "test");
        ASSERT_TRUE(std::memcmp(&a, &b, sizeof a) == 0)
            << code << ", seed " << seed << ", dart " << d << ": " << a.x << " vs " << b.x;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 5000u);
  EXPECT_GT(paths, 0u);  // 2-free darts: some <0,2>- and <1,2>-orbits are paths
}

// Memo mode's loads read the link arrays and the value tables held by the evaluator
// (memoise_collects): the compiled programs give the values of the tree in memo mode (which reads
// through the map and the field; bit for bit, 1e-12 relative with a fused combination) and its
// errors, message and place, on surfaces where some vertices have no position.
TEST(EvaluatorMemo, LoadsThroughHeldTablesGiveTheTreesValuesAndErrors) {
  const std::vector<EmbeddingSignature> sigs{{"position", OrbitType{1, 2}, ValueType::Point}};
  CheckContext ctx;
  ctx.nodes = {"n0"};
  ctx.embeddings = sigs;
  std::vector<std::pair<std::string, ValueType>> codes;
  for (const auto& [code, t] : kMemoExpressions) codes.emplace_back(code, t);
  for (const char* code :
       {"(3 * (n0.position + n0@0.position) + n0@1@0.position + n0@2@1@0.position) / 8",
        "middle([x@2@0.position | x in <1,2>/<>(n0)])", "n0@1@0.position"})
    codes.emplace_back(code, ValueType::Point);
  size_t compared = 0, errors = 0;
  for (uint64_t seed = 0; seed < 30; ++seed) {
    gt::Rng rng(1100 + seed);
    const Map g = varied_surface(seed, rng);
    EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
    for (Dart r : orbit_representatives(g, OrbitType{1, 2}))
      if (seed % 4 != 3 ||
          gt::uniform(rng, 0, 9) != 0)  // every fourth surface: a few vertices without position
        pos.values.set(g, r,
                       {static_cast<double>(gt::uniform(rng, 0, 1000)) / 7.0,
                        static_cast<double>(gt::uniform(rng, 0, 1000)) / 3.0,
                        static_cast<double>(gt::uniform(rng, 0, 1000)) / 11.0});
    for (const auto& [code, type] : codes) {
      auto e = parse_expression(code);
      check_expression(*e, ctx, type);
      const std::optional<Program> program = compile_program(*e);
      ASSERT_TRUE(program.has_value());
      Evaluator tree(g, sigs, {&pos});
      Evaluator held(g, sigs, {&pos});
      tree.memoise_collects(true);
      held.memoise_collects(true);
      for (Dart d : g.darts()) {
        Val a, b;
        std::string ea, eb;
        try {
          a = tree.evaluate(*e, &d, type, "test");
        } catch (const Error& x) {
          ea = x.what();
        }
        try {
          b = held.evaluate(*program, &d, type, "test");
        } catch (const Error& x) {
          eb = x.what();
        }
        ASSERT_EQ(ea, eb) << code << ", seed " << seed << ", dart " << d;
        if (!ea.empty()) {
          ++errors;
          continue;
        }
        if (program->fused)
          ASSERT_TRUE(memo_close(a.x, b.x) && memo_close(a.y, b.y) && memo_close(a.z, b.z) &&
                      memo_close(a.w, b.w))
              << code << ", seed " << seed << ", dart " << d;
        else
          ASSERT_TRUE(std::memcmp(&a, &b, sizeof a) == 0)
              << code << ", seed " << seed << ", dart " << d << ": " << a.x << " vs " << b.x;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 5000u);
  EXPECT_GT(errors, 10u);  // the error path of the held loads is exercised
}

}  // namespace
