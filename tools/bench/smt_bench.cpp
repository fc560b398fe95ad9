// Time to a verdict of the two bounded engines (checker/smt/rule_verifier.hpp) as the bound grows,
// in one run: the SMT engine (Z3) and the exhaustive enumerator on the same rules, maps of 4..10
// darts, rules of 1..4 nodes. The rules are identity rules on a path of m nodes of a 2-G-map
// (a0 -0- a1 -1- a2 -0- a3, every node preserved): they preserve the model, so each engine must
// cover every map of the bound (no early counterexample). The enumerator is run only while its
// family of maps is small enough (GMR_BENCH_ENUM_MAX darts, default 6: map_family is a brute force
// over the involutions of k darts). tools/bench/run_smt.sh prints the table.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "checker/smt/rule_space.hpp"
#include "checker/smt/rule_verifier.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
Rule path_rule(int m) {
  graph::DGraph L, R;
  for (int k = 0; k < m; ++k) {
    L.add_node("a" + std::to_string(k));
    R.add_node("a" + std::to_string(k));
  }
  for (int k = 0; k + 1 < m; ++k) {
    L.add_link(k, k + 1, k % 2);
    R.add_link(k, k + 1, k % 2);
  }
  return Rule(std::move(L), std::move(R), 2, MapKind::GMap, "path" + std::to_string(m));
}

unsigned enum_max() {
  const char* s = std::getenv("GMR_BENCH_ENUM_MAX");
  return s ? static_cast<unsigned>(std::atoi(s)) : 6;
}

void BM_Smt(benchmark::State& st) {
  const Rule r = path_rule(static_cast<int>(st.range(1)));
  const unsigned bound = static_cast<unsigned>(st.range(0));
  bool preserves = true;
  for (auto _ : st) preserves = verify_smt(r, bound).preserves;
  st.counters["preserves"] = preserves;
}

void BM_Enum(benchmark::State& st) {
  const unsigned bound = static_cast<unsigned>(st.range(0));
  if (bound > enum_max()) {
    st.SkipWithError("enumerator bound above GMR_BENCH_ENUM_MAX");
    for (auto _ : st) {
    }
    return;
  }
  const Rule r = path_rule(static_cast<int>(st.range(1)));
  bool preserves = true;
  for (auto _ : st) preserves = verify_enum(r, bound).preserves;
  st.counters["preserves"] = preserves;
}
// Encoding choices (docs/verify.md), on the 2-node path rule at 6 and 7 darts: 0 the default
// (bit-vector darts, fixed match, incremental, local violations), 1 integer darts, 2 free match,
// 3 a fresh solver per bound, 4 violations looked for at every node.
void BM_SmtVariant(benchmark::State& st) {
  const Rule r = path_rule(2);
  EncodingOptions o;
  switch (st.range(1)) {
    case 1: o.sort = DartSort::Int; break;
    case 2: o.fixed_match = false; break;
    case 3: o.incremental = false; break;
    case 4: o.local_violations = false; break;
    default: break;
  }
  for (auto _ : st) benchmark::DoNotOptimize(verify_smt(r, static_cast<unsigned>(st.range(0)), o).preserves);
}
// The 2931 rules of the 1-G-map family (2 nodes, labels 0 and 1) at 4 darts, consistency
// semantics: arg 0 one SmtSession for all, arg 1 a fresh verification (context, solver) per rule.
void BM_FamilySession(benchmark::State& st) {
  EncodingOptions o;
  o.semantics = Semantics::Consistency;
  size_t breaks = 0;
  for (auto _ : st) {
    breaks = 0;
    SmtSession session({1, MapKind::GMap}, 4, 2, o);
    for_each_rule(1, MapKind::GMap, 2, {0, 1}, [&](size_t, const Rule& r) {
      breaks += !(st.range(0) == 0 ? session.verify(r) : verify_smt(r, 4, o)).preserves;
      return true;
    });
  }
  st.counters["breaks"] = static_cast<double>(breaks);
}
}  // namespace

BENCHMARK(BM_FamilySession)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SmtVariant)->ArgsProduct({{6, 7, 8}, {0, 1, 2, 3, 4}})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Smt)->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Enum)->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
