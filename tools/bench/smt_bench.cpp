// Time to a verdict of the two bounded engines (checker/smt/rule_verifier.hpp) as the bound grows,
// in one run: the SMT engine (Z3) and the exhaustive enumerator on the same rules, maps of 4..10
// darts, rules of 1..4 nodes. The rules are identity rules on a path of m nodes of a 2-G-map
// (a0 -0- a1 -1- a2 -0- a3, every node preserved): they preserve the model, so each engine must
// cover every map of the bound (no early counterexample). The enumerator is run only while its
// family of maps is small enough (GMR_BENCH_ENUM_MAX darts, default 6: map_family is a brute force
// over the involutions of k darts). Then the thesis conditions validated on the whole family of
// 1-G-map rules of at most m nodes: the symbolic engine against the enumerator rule by rule.
// tools/bench/run_smt.sh prints the tables and plots them.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "checker/smt/condition_registry.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/rule_verifier.hpp"
#include "checker/smt/symbolic_validation.hpp"

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
    const graph::Node a(static_cast<uint32_t>(k)), b(static_cast<uint32_t>(k + 1));
    L.add_link(a, b, k % 2);
    R.add_link(a, b, k % 2);
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
    case 1:
      o.sort = DartSort::Int;
      break;
    case 2:
      o.fixed_match = false;
      break;
    case 3:
      o.incremental = false;
      break;
    case 4:
      o.local_violations = false;
      break;
    default:
      break;
  }
  for (auto _ : st)
    benchmark::DoNotOptimize(verify_smt(r, static_cast<unsigned>(st.range(0)), o).preserves);
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
// The thesis conditions validated on the whole family of 1-G-map rules of at most m nodes (labels
// 0 and 1), maps of at most k darts: the symbolic engine (one query per direction) ...
ValidationOptions family_options(unsigned darts, int nodes) {
  ValidationOptions o;
  o.n = 1;
  o.labels = {0, 1};
  o.max_nodes = nodes;
  o.bound = darts;
  return o;
}
void BM_Symbolic(benchmark::State& st) {
  const ValidationOptions o =
      family_options(static_cast<unsigned>(st.range(0)), static_cast<int>(st.range(1)));
  bool valid = false;
  for (auto _ : st) {
    const SymbolicReport r = validate_symbolic("thesis", o);
    valid = r.sound() && r.complete();
  }
  st.counters["valid"] = valid;
}
// ... and rule by rule with the enumerator (only while the family and the maps are small:
// GMR_BENCH_FAMILY_MAX_NODES nodes, default 2, and GMR_BENCH_ENUM_MAX darts).
void BM_FamilyEnum(benchmark::State& st) {
  const char* s = std::getenv("GMR_BENCH_FAMILY_MAX_NODES");
  const int max_nodes = s ? std::atoi(s) : 2;
  if (st.range(0) > enum_max() || st.range(1) > max_nodes) {
    st.SkipWithError(
        "family too large for the enumerator (GMR_BENCH_ENUM_MAX, GMR_BENCH_FAMILY_MAX_NODES)");
    for (auto _ : st) {
    }
    return;
  }
  ValidationOptions o =
      family_options(static_cast<unsigned>(st.range(0)), static_cast<int>(st.range(1)));
  o.engine = Engine::Enum;
  const BuiltinCondition* c = find_builtin_condition("thesis");
  bool valid = false;
  for (auto _ : st) {
    const ValidationReport r = validate_condition(
        "thesis",
        [&](const std::vector<Rule>& rules) {
          std::vector<bool> out;
          for (const auto& x : rules) out.push_back(c->holds(x));
          return out;
        },
        o);
    valid = r.sound() && r.complete();
  }
  st.counters["valid"] = valid;
}
}  // namespace

BENCHMARK(BM_FamilySession)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SmtVariant)
    ->ArgsProduct({{6, 7, 8}, {0, 1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Smt)
    ->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Enum)
    ->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Symbolic)
    ->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_FamilyEnum)
    ->ArgsProduct({{4, 5, 6, 7, 8, 9, 10}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_MAIN();
