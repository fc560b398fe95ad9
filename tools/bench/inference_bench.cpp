// Inference by topological folding (docs/inference.md), timed on the inference paper's examples
// (seed §9: Powell–Sabin 6-split ≈ 5 ms, Doo–Sabin 3rd iteration ≈ 40 ms, (2,2,2)-Menger ≈ 150 ms
// in Jerboa), on quad subdivisions of tori of 10^3 .. 10^6 darts (before + after: time per dart),
// and against a naive driver in the same run. tools/bench/inference.sh runs it and plots.
//
// What is timed, for each example: the joint graph κ(G,H) of the pair (identity or corner mapping)
// and the driver (infer.hpp) on the given orbit type: folding, the split into L and R, the scheme
// checker and de-duplication.
// The naive baseline: every L dart is a start (no marking), and every candidate rule is re-checked
// by instantiation (applied to G at its start dart) and isomorphism of the result with H
// (signatures' word comparison, model/core/signature.hpp) — what the driver's marking and
// rule-scheme isomorphism (Alg. 7) avoid.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "inference/dart_mapping.hpp"
#include "inference/infer.hpp"
#include "inference/inference_format.hpp"
#include "inference/tests/polycube_support.hpp"
#include "model/core/builders.hpp"
#include "model/core/signature.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"

using namespace gmr;
using namespace gmr::inference;
using gmr::scheme::RuleScheme;

namespace {

std::string rule_path(const std::string& name) {
  return std::string(GMR_RULES_DIR) + "/" + name + ".json";
}

struct Example {
  Map before{2}, after{2};
  DartMapping mapping;
  OrbitType orbit;
  size_t right_nodes = 0;  // expected size of R
};

// Triangle -> Powell–Sabin 6-split, built by library operations in sequence (6 -> 36 darts).
Example powell_sabin() {
  const RuleScheme vi = io::read_scheme_file(rule_path("vertex_insertion"));
  const RuleScheme ft = io::read_scheme_file(rule_path("face_triangulation"));
  Example ex;
  ex.before = make_polygon(3);
  ex.after = ex.before;
  for (Dart e : {Dart{0}, Dart{2}, Dart{4}}) scheme::apply(scheme::SchemeEngine(vi), ex.after, {e});
  scheme::apply(scheme::SchemeEngine(ft), ex.after, {0});
  ex.mapping = identity_mapping(ex.before, ex.after);
  ex.orbit = OrbitType{0, 1, 2};
  ex.right_nodes = 6;
  return ex;
}

// Cube -> three Doo–Sabin steps (48 -> 3072 darts); R = 64 nodes.
Example doo_sabin_3() {
  const RuleScheme ds = io::read_scheme_file(rule_path("doo_sabin_subdivision"));
  Example ex;
  ex.before = make_cube();
  ex.after = ex.before;
  for (int k = 0; k < 3; ++k) scheme::apply(scheme::SchemeEngine(ds), ex.after, {0});
  ex.mapping = identity_mapping(ex.before, ex.after);
  ex.orbit = OrbitType{0, 1, 2};
  ex.right_nodes = 64;
  return ex;
}

// Two glued cubes -> their (2,2,2)-Menger polycubes (96 -> 7776 darts); R = 81 nodes.
Example menger_222() {
  const test::polycube::PolycubeSubdivision s({{0, 0, 0}, {0, 0, 1}},
                                              menger_polycube_voxels(2, 2, 2), 5);
  Example ex;
  ex.before = s.before;
  ex.after = s.after;
  ex.mapping = s.mapping;
  ex.orbit = OrbitType::range(0, 3);
  ex.right_nodes = 81;
  return ex;
}

// A w x h torus and its quad subdivision by the library scheme (before + after = 40wh darts).
Example quad_torus(size_t w, size_t h) {
  const RuleScheme qs = io::read_scheme_file(rule_path("quad_subdivision"));
  Example ex;
  ex.before = make_torus(w, h);
  ex.after = ex.before;
  scheme::apply(scheme::SchemeEngine(qs), ex.after, {0});
  ex.mapping = identity_mapping(ex.before, ex.after);
  ex.orbit = OrbitType{0, 1, 2};
  ex.right_nodes = 4;
  return ex;
}

void expect_one_rule(const InferenceResult& r, const Example& ex, benchmark::State& st) {
  if (r.rules.size() != 1 || r.rules[0].scheme.right.size() != ex.right_nodes)
    st.SkipWithError(("unexpected inference result:\n" + to_text(r)).c_str());
}

InferenceResult driver(const Example& ex) {
  InferOptions opt;
  opt.orbit = ex.orbit;
  return infer_rules(joint_from_pair(ex.before, ex.after, ex.mapping), opt);
}

// The naive baseline: every start, every candidate instantiated and compared with H.
size_t naive(const Example& ex) {
  const JointGraph j = joint_from_pair(ex.before, ex.after, ex.mapping);
  FoldWorkspace ws(j.size());
  size_t confirmed = 0;
  for (uint32_t a = 0; a < j.size(); ++a) {
    if (j.side(a) != Side::L) continue;
    const FoldResult f = fold(j, ex.orbit, a, {}, &ws);
    if (!f.ok()) continue;
    const InferredRule r = rule_from_fold(f, j);
    if (!r.accepted()) continue;
    std::vector<Dart> hooks;
    for (uint32_t h : r.scheme.hook_nodes()) hooks.push_back(r.left_darts[h][0]);
    auto [got, app] =
        scheme::apply(scheme::SchemeEngine(r.scheme), std::as_const(ex.before), hooks);
    if (app.applied && is_isomorphic(got, ex.after)) ++confirmed;
  }
  return confirmed;
}

void run_driver(benchmark::State& st, const Example& ex) {
  const size_t darts = ex.before.size() + ex.after.size();
  for (auto _ : st) {
    const InferenceResult r = driver(ex);
    benchmark::DoNotOptimize(r.rules.data());
    expect_one_rule(r, ex, st);
  }
  st.counters["darts"] = static_cast<double>(darts);
  st.counters["ns_per_dart"] = benchmark::Counter(
      static_cast<double>(darts) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void run_naive(benchmark::State& st, const Example& ex) {
  const size_t darts = ex.before.size() + ex.after.size();
  for (auto _ : st) {
    const size_t n = naive(ex);
    benchmark::DoNotOptimize(n);
    if (n == 0) st.SkipWithError("the naive baseline confirmed no rule");
  }
  st.counters["darts"] = static_cast<double>(darts);
}

const Example& cached(int which) {
  static const Example ps = powell_sabin(), ds = doo_sabin_3(), mg = menger_222();
  switch (which) {
    case 0:
      return ps;
    case 1:
      return ds;
    default:
      return mg;
  }
}

// Tori with before + after ≈ 10^k darts (40wh darts, w = h).
const Example& torus_for(int64_t target) {
  static std::map<int64_t, Example> cache;
  auto it = cache.find(target);
  if (it != cache.end()) return it->second;
  const auto side = static_cast<size_t>(std::lround(std::sqrt(static_cast<double>(target) / 40.0)));
  return cache.emplace(target, quad_torus(side, side)).first->second;
}

void paper_driver(benchmark::State& st) { run_driver(st, cached(static_cast<int>(st.range(0)))); }
void paper_naive(benchmark::State& st) { run_naive(st, cached(static_cast<int>(st.range(0)))); }
void linear_driver(benchmark::State& st) { run_driver(st, torus_for(st.range(0))); }
void linear_naive(benchmark::State& st) { run_naive(st, torus_for(st.range(0))); }

}  // namespace

// Arguments: 0 Powell–Sabin, 1 Doo–Sabin 3rd iteration, 2 (2,2,2)-Menger.
BENCHMARK(paper_driver)->Name("infer/paper/gmr")->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(paper_naive)->Name("infer/paper/naive")->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(linear_driver)
    ->Name("infer/quad_torus/gmr")
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(10000)
    ->Arg(30000)
    ->Arg(100000)
    ->Arg(300000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);
// Quadratic: up to 10^4 darts.
BENCHMARK(linear_naive)
    ->Name("infer/quad_torus/naive")
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
