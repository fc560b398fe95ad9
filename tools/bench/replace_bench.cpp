// Query by signature against testing each pattern by isomorphism (Damiand & Nivoliers 2022 §6.3,
// Table 2 "time-qrn"): the 6209 hex-conformal configurations are looked up among the 226
// unoriented class representatives (flagged boundaries), (a) by the pattern store as
// query-replace uses it (PatternStore::match: profile, then one word comparison or the signature
// and the hash table), (b) by computing each configuration's signature and hashing it, (c) by the
// core isomorphism test (Theorem 1, O(n^2) per test) against each representative in turn until
// one fits. All find the class of every configuration (the store's patterns are the
// representatives lifted to 3-G-maps, boundary only).
#include <benchmark/benchmark.h>

#include <unordered_map>

#include "model/core/builders.hpp"
#include "model/core/signature.hpp"
#include "model/replace/configurations.hpp"
#include "model/replace/pattern_store.hpp"

namespace {

using namespace gmr;
using namespace gmr::replace;

struct Data {
  ConfigurationSet set = generate_configurations("hex-conformal");
  std::vector<size_t> reps;  // one configuration per class
  std::unordered_map<Word, size_t, WordHash> table;
  PatternStore store{Mode::Unoriented};
  Data() {
    for (size_t i = 0; i < set.configurations.size(); ++i) {
      const Configuration& c = set.configurations[i];
      const Word key = store_key(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3, Mode::Unoriented);
      if (table.emplace(key, reps.size()).second) reps.push_back(i);
    }
    for (size_t r : reps) {
      const Configuration& c = set.configurations[r];
      FlaggedMap m{lift(c.map.map, 3), c.map.flag, {}};
      store.add(make_pattern("class" + std::to_string(r), std::move(m)));
    }
  }
};
const Data& data() {
  static const Data d;
  return d;
}

void BM_QueryByPatternStore(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations)
      found += d.store.match(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3).hits != nullptr;
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
}

void BM_QueryBySignature(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations) {
      const Word key = store_key(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3, Mode::Unoriented);
      found += d.table.count(key);
    }
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
}

void BM_QueryByIsomorphismTests(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations)
      for (size_t r : d.reps) {
        const Configuration& p = d.set.configurations[r];
        if (is_isomorphic(p.map.map, c.map.map, &p.map.flag, &c.map.flag)) {
          ++found;
          break;
        }
      }
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
}

BENCHMARK(BM_QueryByPatternStore)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueryBySignature)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueryByIsomorphismTests)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
